// The whole `scalcal reproduce` run: every stage in order (programs, then figures and tables), then
// REPORT.md with the paper's stated numbers at the top and the timings at the end.
#pragma once
#include "experiments/reproduce/context.hpp"

namespace scalcal::reproduce {

struct RunSummary {
  std::filesystem::path report;  // REPORT.md
  double seconds = 0;
};

// Creates options.out when missing. Throws std::runtime_error when a file cannot be written.
RunSummary run(const Options& options, bool show_progress);

}  // namespace scalcal::reproduce
