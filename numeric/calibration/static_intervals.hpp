// Static positions in a raw log: where the meter stood still. The variance of each output over a
// moving window, its norm over the three outputs, is compared with the same norm over the log's
// initial still period: a sample is static where it stays below threshold_factor times that
// (the noise of the sensor at rest, so no units or sensor type enter). Runs of static samples of
// at least min_seconds are the intervals; non-finite and saturated samples break a run and are
// counted, never dropped silently. The idea is IMU-TK's (Tedaldi et al. 2014); so are the defaults'
// orders of magnitude.
#pragma once
#include <string>
#include <vector>

#include "numeric/io/raw_log.hpp"

namespace scalcal {

struct StaticIntervalOptions {
  double still_seconds = 30;     // the initial still period: its noise sets the threshold
  double window_seconds = 1;     // the moving variance's window (an odd number of samples, at least 11)
  double threshold_factor = 6;   // static below this times the still period's variance norm
  double min_seconds = 1;        // shorter runs are not positions
};

struct StaticInterval {
  int begin = 0, end = 0;        // sample indices, inclusive
  double start = 0, stop = 0;    // their times (seconds)
  int samples() const { return end - begin + 1; }
};

struct IntervalDetection {
  std::vector<StaticInterval> intervals;
  double sample_period = 0;      // the median time step, seconds
  int window = 0;                // samples
  double still_variance = 0;     // the still period's variance norm (file units squared)
  double threshold = 0;          // what a window's variance norm must stay below
  int nonfinite = 0;             // rows with a NaN or infinite value
  int saturated = 0;             // samples at an output's extreme and at an ADC rail (0, 2^k or 2^k - 1), three or more in a row
  std::vector<int> nonfinite_lines, saturated_lines;  // the first few of each, for messages
};

// Throws InputError (the log's file) when the still period is shorter than the window, or not
// still at all (its variance is zero: a constant or clipped signal).
IntervalDetection detect_static_intervals(const RawLog& log, const StaticIntervalOptions& options = {});

}  // namespace scalcal
