// `scalcal evaluate PROGRAM --model BASE+Tk --temperature T1..T2`: a thermal program's criteria (rows
// x,y,z,t_c; numeric/thermal/thermal_program.hpp) and its efficiency against the thermal limits
// (Theorem 25). A program whose temperatures or positions cannot identify the model is refused with
// what it lacks.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "commands/core/json.hpp"
#include "commands/core/warning.hpp"
#include "commands/design/thermal_limits.hpp"
#include "numeric/thermal/thermal_program.hpp"

namespace scalcal::commands {

struct ThermalEvaluation {
  std::string name;
  ThermalModel model;
  TemperatureRange range;
  ThermalProgram program;
  std::vector<double> setpoints;  // the distinct temperatures, increasing (degrees Celsius)
  double condition = 0;           // lambda_max / lambda_min of the information matrix
  std::array<std::optional<double>, kCriterionCount> values{}, efficiency{};
  ThermalLimitsResult limits;
  Warnings warnings;
};

// Throws InputError naming the program for one that cannot identify the model.
// With a region, the efficiencies are against region x [T1, T2]'s limits (thermal_limits.hpp).
ThermalEvaluation evaluate_thermal(const std::string& name, const ThermalProgram& program, const ThermalModel& model,
                                   const TemperatureRange& range, const std::optional<Region>& region = {},
                                   const Progress& progress = {});

Json to_json(const ThermalEvaluation& e);

}  // namespace scalcal::commands
