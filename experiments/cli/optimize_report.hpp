// `scalcal optimize` as a function: the optimal program of N positions for one criterion, on the
// sphere or a region, optionally polished in MPFR. Shared by the CLI and the Python module.
#pragma once
#include <string>
#include <vector>

#include "experiments/cli/options.hpp"
#include "experiments/cli/report.hpp"
#include "numeric/synthesis/multistart.hpp"

namespace scalcal::cli {

inline constexpr IntegerRange kOptimizePositions{3, 1000}, kPolishDigits{1, 1000};

struct OptimizeRequest {
  SynthesisOptions synthesis;        // N, criterion, model, starts, seed, threads, local solver, progress
  std::vector<std::string> regions;  // --region specs; none: the sphere
  int digits = 0;                    // polish to this many digits (0: no polish)
  std::string out;                   // also write the program as CSV here (empty: no file)
};

// Throws UsageError for N below the model's parameters or options the model does not take, and
// InputError for a bad region or a polish asked on a restricted region.
Report optimize_report(const OptimizeRequest& request);

}  // namespace scalcal::cli
