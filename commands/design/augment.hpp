// `scalcal augment` as a function: keeps the lab's positions and adds the K inside the bench's region
// that improve the criterion of the model most (numeric/region/augment.hpp).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "commands/core/common_options.hpp"
#include "commands/core/json.hpp"
#include "commands/core/progress.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/program/program_csv.hpp"
#include "numeric/region/augment.hpp"

namespace scalcal::commands {

struct AugmentRequest {
  std::string name;  // the given program's name in messages
  Program given;
  int add = 0;
  CriterionKind criterion = CriterionKind::D;
  ModelKind model = ModelKind::paper9;
  std::vector<std::string> regions;  // --region specs, else the program file's
  AugmentPolishOptions polish;       // starts of the joint polish, seed, threads
  Warnings warnings;                 // found while reading the request
};

struct AugmentResult {
  CriterionKind criterion = CriterionKind::D;
  ModelKind model = ModelKind::paper9;
  Region region;
  int given = 0;  // positions given
  AugmentedProgram augmented;
  // The region's limit of the criterion (paper9; another model's stated limit on the sphere; none when unknown) and
  // limit / value (D: P-th root):
  // how far the N + K positions are from the best any number of positions could do there.
  std::optional<double> limit, efficiency;
  std::vector<ExtraColumn> columns;  // for the program file on a one-zone region
  Warnings warnings;
};

// --program FILE --add K [--criterion C] [--model NAME] [--region SPEC]... [--starts K] [--seed S]
// [--threads T] [--out FILE] [--json]
const CommandTable& augment_table();
AugmentRequest augment_request(const Values& values);

AugmentResult augment(const AugmentRequest& request, const Progress& progress = {});

Json to_json(const AugmentResult& result);

}  // namespace scalcal::commands
