// `scalcal evaluate` as a function: the criteria of one program under a model, and with a region its
// efficiency against the region's limits (positions outside the region are refused).
#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "commands/core/json.hpp"
#include "commands/core/option_table.hpp"
#include "commands/core/progress.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "commands/design/limits_statement.hpp"
#include "commands/design/thermal_evaluate.hpp"
#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/program/program_csv.hpp"
#include "numeric/region/region.hpp"

namespace scalcal::commands {

struct EvaluateRequest {
  std::string name;  // the program's name in messages (a file, a catalogue name, "positions")
  Program program;
  ModelKind model = ModelKind::paper9;
  std::vector<std::string> regions;     // --region specs, else the program file's; none: the sphere (no efficiencies)
  bool regions_from_file = false;       // regions is the program file's region line (no --region given)
  double tolerance_deg = 0.05;          // positions this far outside the region count as inside
  Warnings warnings;                    // found while reading the request (a region line replaced)
  std::optional<ThermalModel> thermal;  // --model BASE+Tk: then the program is thermal_program
  std::optional<TemperatureRange> temperature;  // --temperature, which a thermal model needs
  ThermalProgram thermal_program;
};

struct EvaluateResult {
  std::string name;
  Program program;
  ModelEvaluation evaluation;
  std::optional<Region> region;  // with --region
  // limit / value per criterion on the region (D as its P-th root); nullopt: no known limit there.
  std::array<std::optional<double>, kCriterionCount> efficiency{};
  std::array<std::optional<ReportedLimit>, kCriterionCount> limits{};  // what each efficiency is against
  std::vector<ExtraColumn> columns;          // tilt and azimuth for a program file, on a one-zone region
  std::optional<ThermalEvaluation> thermal;  // a thermal model's evaluation (then the rest is empty)
  Warnings warnings;
};

// PROGRAM [--model NAME] [--temperature T1..T2] [--region SPEC]... [--tolerance DEG] [--out FILE] [--json]
const CommandTable& evaluate_table();
EvaluateRequest evaluate_request(const Values& values);

// Throws InputError for a rank-deficient program or one with positions outside the region, and
// UsageError for a restricted --region under a model without region limits (a program file's region line is then
// set aside with a warning, and --region sphere restricts nothing).
EvaluateResult evaluate(const EvaluateRequest& request, const Progress& progress = {});

// The evaluation's JSON (evaluation_json.hpp) with `region`, `efficiency` and `limits` (each with its
// status: limits_statement.hpp) when a region was given.
Json to_json(const EvaluateResult& result);

}  // namespace scalcal::commands
