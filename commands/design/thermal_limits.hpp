// `scalcal limits --model BASE+Tk --temperature T1..T2`: a thermal model's limits over positions and
// set-points (Theorem 25, numeric/thermal/product_limits.hpp), each with the optimal set-points in
// degrees Celsius, the exact form where both factors are proven, and the label of what stands behind it.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "commands/core/json.hpp"
#include "commands/core/progress.hpp"
#include "numeric/region/region.hpp"
#include "numeric/thermal/product_limits.hpp"
#include "numeric/thermal/temperature_range.hpp"

namespace scalcal::commands {

struct ThermalLimitRow {
  CriterionKind criterion = CriterionKind::D;
  std::optional<ThermalLimit> limit;  // none: Theorem 25 does not determine it
  std::string exact;                  // "(61509375/4)^4 * (3125/16)^9" where proven, else ""
  // proven (both factors exact), certified (limit->lower_bound .. limit->value encloses it: the region's factor
  // by interval arithmetic, the temperature's exact) or numerical
  std::string status;
  std::string note;  // why there is no limit, or how precise a numerical one is
};

struct ThermalLimitsResult {
  ThermalModel model;
  TemperatureRange range;
  std::optional<Region> region;       // the positions' region (none: the sphere)
  std::vector<ThermalLimitRow> rows;  // every registered criterion
};

// On region x [T1, T2] (Theorem 25's product holds on any region: its proof uses each factor's equivalence
// theorem only) the base model's factor is the region's limit (numeric/region/region_limit.hpp: a cap's closed
// form where a theorem gives one, else certified bounds); a bias-only model has limits on the sphere only.
ThermalLimitsResult thermal_limits(const ThermalModel& model, const TemperatureRange& range,
                                   const std::optional<Region>& region = {}, const Progress& progress = {});
Json to_json(const ThermalLimitsResult& result);

}  // namespace scalcal::commands
