// `scalcal limits` as a function: the N -> infinity limits of the normalised criteria, exact on the
// sphere (symbolic/limits.hpp) or a model's stated limits, and on a region a theorem's closed form where
// one applies (a cap: numeric/region/cap_limits.hpp), certified bounds elsewhere.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "commands/core/common_options.hpp"
#include "commands/core/json.hpp"
#include "commands/core/progress.hpp"
#include "commands/core/warning.hpp"
#include "commands/design/thermal_limits.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/region/region_limit.hpp"

namespace scalcal::commands {

struct LimitsRequest {
  ModelKind model = ModelKind::paper9;
  std::vector<std::string> regions;             // none, or only "sphere": the sphere
  std::optional<ThermalModel> thermal;          // --model BASE+Tk: a thermal model (then `model` is its base)
  std::optional<TemperatureRange> temperature;  // --temperature, which a thermal model needs
};

// One criterion's limit on the sphere: its exact form and the moments of an optimal measure.
struct SphereLimit {
  std::string exact;  // canonical text, "61509375/4"
  double value = 0;
  std::string x4, x2y2, x6;              // E[x^4], E[x^2 y^2], E[x^6] as exact text ("" when not stated)
  std::optional<double> b;               // E[x^2 y^2] as a number
  std::string measure, attained, proof;  // a model's own statement (empty for the paper's model)
  std::string theorem;                   // the document that proves the limit
};

struct CriterionLimits {
  CriterionKind criterion = CriterionKind::D;
  std::optional<SphereLimit> sphere;   // on the sphere (none: no known limit)
  std::optional<RegionLimit> region;   // on the region, when one was given
  std::string region_exact;            // its closed form where a theorem gives one (region->theorem)
  std::optional<double> sphere_value;  // the sphere's limit the region's is compared with
};

struct LimitsResult {
  ModelKind model = ModelKind::paper9;
  std::optional<Region> region;                // when the request names one other than the sphere
  std::vector<CriterionLimits> criteria;       // every registered criterion, in the registry's order
  std::optional<ThermalLimitsResult> thermal;  // a thermal model's limits (then `criteria` is empty)
  Warnings warnings;
};

// [--model NAME] [--temperature T1..T2] [--region SPEC]... [--json]
const CommandTable& limits_table();
LimitsRequest limits_request(const Values& values);

// Throws UsageError for regions under a model other than paper9, InputError for a bad region.
LimitsResult limits(const LimitsRequest& request, const Progress& progress = {});

Json to_json(const LimitsResult& result);

}  // namespace scalcal::commands
