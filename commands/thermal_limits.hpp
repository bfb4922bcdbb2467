// `scalcal limits --model BASE+Tk --temperature T1..T2`: a thermal model's limits over positions and
// set-points (Theorem 25, numeric/thermal/product_limits.hpp), each with the optimal set-points in
// degrees Celsius, the exact form where both factors are proven, and the label of what stands behind it.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "commands/json.hpp"
#include "numeric/thermal/product_limits.hpp"
#include "numeric/thermal/temperature_range.hpp"

namespace scalcal::commands {

struct ThermalLimitRow {
  CriterionKind criterion = CriterionKind::D;
  std::optional<ThermalLimit> limit;  // none: Theorem 25 does not determine it
  std::string exact;                  // "(61509375/4)^4 * (3125/16)^9" where proven, else ""
  std::string status;                 // "proven" or "numerical"
  std::string note;                   // why there is no limit, or how precise a numerical one is
};

struct ThermalLimitsResult {
  ThermalModel model;
  TemperatureRange range;
  std::vector<ThermalLimitRow> rows;  // every registered criterion
};

ThermalLimitsResult thermal_limits(const ThermalModel& model, const TemperatureRange& range);
Json to_json(const ThermalLimitsResult& result);

}  // namespace scalcal::commands
