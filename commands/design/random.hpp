// `scalcal random` as a function: the best of R uniform random programs (the paper's dashed line,
// R = 100000) on all cores; on a restricted region, uniform on it.
#pragma once
#include <string>
#include <vector>

#include "commands/core/common_options.hpp"
#include "commands/core/json.hpp"
#include "commands/core/progress.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/synthesis/random_search.hpp"

namespace scalcal::commands {

struct RandomRequest {
  int positions = 0;
  long long count = 0;
  std::uint64_t seed = 1;
  CriterionKind criterion = CriterionKind::D;
  ModelKind model = ModelKind::paper9;
  std::vector<std::string> regions;
  int threads = 0;
};

struct RandomResult {
  RandomRequest request;
  RandomSearchResult search;
  std::string region;  // the region's text on a restricted region, "" on the sphere
  Warnings warnings;
};

// --positions N --count R [--seed S] [--criterion C] [--model NAME] [--region SPEC]... [--threads T] [--json]
const CommandTable& random_table();
RandomRequest random_request(const Values& values);

// Throws UsageError for N below the model's parameters, InputError for a bad region.
RandomResult random_programs(const RandomRequest& request, const Progress& progress = {});

Json to_json(const RandomResult& result);

}  // namespace scalcal::commands
