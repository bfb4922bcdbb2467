// `scalcal plan` as a function: the settings of a bench for each position of a program and an order
// to run them (fewest remounts, then least travel: numeric/bench/run_order.hpp), each setting on the
// bench's resolution without leaving the program's region, and what that rounding costs.
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
#include "numeric/bench/run_order.hpp"
#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/program/program_csv.hpp"
#include "numeric/region/region.hpp"

namespace scalcal::commands {

struct PlanRequest {
  std::string name;  // the program's name in messages
  Program program;
  std::string bench;          // the --bench spec
  double resolution_deg = 0;  // 0: the angles as solved
  double max_loss = 0.05;     // the share of D efficiency rounding may cost (--max-loss / 100)
  RunOrder order = RunOrder::travel;
  std::vector<std::string> regions;  // --region, else the program file's; none: no region to keep
  ModelKind model = ModelKind::paper9;
  Warnings warnings;  // found while reading the request
  // A thermal program's (a temperature column): each row's temperature, and the time per set-point and per
  // position (thermal_plan.hpp); empty for a program without temperatures.
  std::vector<double> celsius;
  double soak_s = 1800, dwell_s = 5;
};

// A set-point of a thermal plan: its steps are steps[first_step .. first_step + steps - 1].
struct SetPointRun {
  double celsius = 0;  // the mean of its rows' temperatures
  int first_step = 0, steps = 0;
};

struct PlannedStep {
  int position = 0;         // index into the program (0-based; 1-based in text, JSON and CSV)
  BenchSetting setting;     // on the resolution grid
  Vec3 eta;                 // the position the setting measures
  double rounding_deg = 0;  // its angle from the designed position
};

struct PlanResult {
  explicit PlanResult(Bench b) : bench(std::move(b)) {}
  std::string name;
  Bench bench;
  std::optional<Region> region;
  RunOrder order = RunOrder::travel;
  double resolution_deg = 0;
  std::vector<PlannedStep> steps;  // in run order
  double travel_deg = 0;
  int remounts = 0;
  double given_travel_deg = 0;  // the program's own order, with its best settings, rounded alike
  int given_remounts = 0;
  ModelKind model = ModelKind::paper9;
  ModelEvaluation designed, as_run;  // the criteria before and after rounding
  // 1 - efficiency as run / efficiency designed = 1 - value designed / value as run (D: P-th roots):
  // the share of the design's efficiency that rounding costs, whatever the region's limit.
  std::array<double, kCriterionCount> efficiency_lost{};
  Warnings warnings;
  // A thermal plan's: each position's temperature, the set-points in run order, and the time (seconds):
  // soak per set-point, rest per position, the total with the axes' travel at kTravelDegPerSecond.
  std::vector<double> celsius;
  std::vector<SetPointRun> setpoints;
  double soak_s = 0, dwell_s = 0, total_s = 0;

  double max_rounding_deg() const;
  Program program_as_run() const;  // the steps' positions, in run order
};

const char* order_name(RunOrder order);

// PROGRAM --bench SPEC [--resolution DEG] [--order travel|remounts|given] [--region SPEC]... [--model NAME]
// [--soak MIN] [--dwell S] [--out FILE] [--json]
const CommandTable& plan_table();
PlanRequest plan_request(const Values& values);

// Throws InputError for a bad bench spec, a position the bench cannot reach (naming it), or one that
// no setting on the resolution grid keeps inside the region; UsageError when the rounding costs more
// than max_loss of the design's D efficiency.
PlanResult plan(const PlanRequest& request, const Progress& progress = {});
// The criteria as designed and as run, and the share of efficiency the rounding lost (r.steps set).
void judge_rounding(const PlanRequest& request, PlanResult& result);

Json to_json(const PlanResult& result);

// The plan as a program file: the positions as run, in run order, with columns step, position, the
// mounting and the angles, after the region line and comments naming the bench and its mountings.
struct PlanFile {
  Program program;
  std::vector<ExtraColumn> columns;
  ProgramNotes notes;
};
PlanFile plan_file(const PlanResult& result);

}  // namespace scalcal::commands
