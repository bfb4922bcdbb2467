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
// Progress goes to stderr as `progress` says: ProgressMode::off for --quiet, else
// progress_mode(false, stderr is a terminal) (lines into a log, one line rewritten on a terminal).
RunSummary run(const Options& options, ProgressMode progress);

}  // namespace scalcal::reproduce
