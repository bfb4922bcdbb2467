// `scalcal optimize` as a function: the optimal program of N positions for one criterion, on the
// sphere or a region, optionally polished in MPFR, with the limit it is judged against.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands/core/common_options.hpp"
#include "commands/core/json.hpp"
#include "commands/core/progress.hpp"
#include "commands/core/warning.hpp"
#include "commands/design/limits_statement.hpp"
#include "numeric/polish/polish.hpp"
#include "numeric/program/program_csv.hpp"
#include "numeric/region/region.hpp"
#include "numeric/synthesis/multistart.hpp"
#include "numeric/thermal/temperature_range.hpp"
#include "numeric/thermal/thermal_model.hpp"

namespace scalcal::commands {

struct ThermalOptimizeResult;  // thermal_optimize.hpp

struct OptimizeRequest {
  SynthesisOptions synthesis;           // N (0: --from gives it), criterion, model, starts, seed, threads, local solver
  std::string from;                     // start 0 is this program (a catalogue name or a file); "" none
  std::optional<Program> start;         // that program, when given as data (else read from `from`)
  std::vector<std::string> regions;     // --region specs; none: the sphere
  double margin_deg = 0;                // design this far inside the region's boundaries
  int digits = 0;                       // polish to this many digits (0: no polish)
  std::optional<ThermalModel> thermal;  // --model BASE+Tk: a product over set-points (thermal_optimize.hpp)
  std::optional<TemperatureRange> temperature;  // --temperature, which a thermal model needs
};

struct OptimizeResult {
  CriterionKind criterion = CriterionKind::D;
  ModelKind model = ModelKind::paper9;
  int positions = 0;
  SynthesisResult synthesis;
  std::optional<PolishResult> polished;
  Program program;   // the best: the polished one when there is a polish
  double value = 0;  // the criterion of `program`: the multistart's, or the polished program's evaluated in double
  std::optional<Region> region;       // with --region (as given: the limit and the program file's region line)
  std::optional<Region> designed_on;  // with --margin: the region inset by the margin, where positions lie
  std::optional<double> limit;        // the region's, or the model's stated limit; none when unknown
  std::optional<ReportedLimit> limit_statement;  // the same with its status, theorem and exact form
  std::optional<double> efficiency;
  std::vector<ExtraColumn> columns;                      // for the program file on a one-zone region
  std::shared_ptr<const ThermalOptimizeResult> thermal;  // a thermal model's result (then the rest is its sphere run's)
  Warnings warnings;
};

inline constexpr IntegerRange kOptimizePositions{3, 1000}, kPolishDigits{1, 1000};

// --positions N|--from PROGRAM --criterion C [--model NAME] [--temperature T1..T2] [--region SPEC]... [--margin DEG]
// [--starts K] [--seed S]
// [--threads T] [--digits P] [--local auto|newton|lbfgs|ipopt] [--out FILE] [--json]
const CommandTable& optimize_table();
OptimizeRequest optimize_request(const Values& values);

// Throws UsageError for N below the model's parameters or options the model does not take, and
// InputError for a bad region or a polish asked on a restricted region.
OptimizeResult optimize(const OptimizeRequest& request, const Progress& progress = {});

Json to_json(const OptimizeResult& result);

}  // namespace scalcal::commands
