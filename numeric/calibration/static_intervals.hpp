// Static positions in a raw log: where the meter stood still. The variance of each output over a
// moving window, its norm over the three outputs, is compared with the noise floor of the sensor at
// rest: a sample is static where it stays below threshold_factor times that (so no units or sensor
// type enter). Runs of static samples of at least min_seconds are the intervals; non-finite and
// saturated samples break a run and are counted, never dropped silently. The idea is IMU-TK's
// (Tedaldi et al. 2014), and so are the defaults' orders of magnitude; but IMU-TK (and this code
// before) takes the noise floor from an initial still period, which a log that starts with motion
// does not have. Here the floor comes from the log itself: the quiet windows are those below 3 times
// the 5 % quantile of all windows' variance norms, and the floor is their median (the typical still
// window, not the quietest). A log that is still for less than 5 % of its windows has too few
// positions anyway. `still_seconds` > 0 restores the initial-period floor.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "numeric/calibration/raw_log.hpp"

namespace scalcal {

// A still run whose direction turns by more than this (radians, two degrees) between its first and
// last thirds is slow motion, not a pose. A pose that turns less is still a pose for the modulus: the
// mean of an arc of 2 degrees falls short of the sphere by 5e-5 of the radius (theta^2 / 24), below
// the scatter between hand-held poses (1e-4 on the Xsens log).
inline constexpr double kPoseDriftRad = 2 * 3.14159265358979323846 / 180;

struct StaticIntervalOptions {
  double still_seconds = 0;     // > 0: the initial still period of this length sets the floor; 0: the quiet windows
  double window_seconds = 1;    // the moving variance's window (an odd number of samples, at least 11)
  double threshold_factor = 6;  // static below this times the still period's variance norm
  double min_seconds = 1;       // shorter runs are not positions
};

struct StaticInterval {
  int begin = 0, end = 0;      // sample indices, inclusive
  double start = 0, stop = 0;  // their times (seconds)
  // Short breaks inside (sample index ranges, inclusive) where a noisy window crossed the threshold:
  // the pose goes on, these samples are not its.
  std::vector<std::pair<int, int>> breaks;
  int samples() const {
    int n = end - begin + 1;
    for (const auto& [a, b] : breaks) n -= b - a + 1;
    return n;
  }
  bool in_break(int i) const {
    for (const auto& [a, b] : breaks)
      if (i >= a && i <= b) return true;
    return false;
  }
};

struct IntervalDetection {
  std::vector<StaticInterval> intervals;
  double sample_period = 0;       // the median time step, seconds
  int window = 0;                 // samples
  double still_variance = 0;      // the noise floor: a still window's variance norm (file units squared)
  bool floor_from_still = false;  // the floor came from the initial still period (--still), not the quiet windows
  double threshold = 0;           // what a window's variance norm must stay below
  int short_runs = 0;             // static runs shorter than min_seconds (not positions)
  int drifting_runs = 0;          // runs long enough that turn while "still" (slow motion, not poses)
  double longest_fraction = 0;    // the longest interval's share of the log's samples
  int nonfinite = 0;              // rows with a NaN or infinite value
  int saturated = 0;  // samples at an output's extreme and at an ADC rail (0, 2^k or 2^k - 1), three or more in a row
  std::vector<int> nonfinite_lines, saturated_lines;  // the first few of each, for messages
  std::vector<char> usable;                           // per sample: finite and not saturated
};

// The variance norm of the window of w samples centred on each sample (the sum of squares shifted
// by `shift`, a sample of the log, for accuracy); NaN where the window is incomplete or holds an
// unusable sample.
std::vector<double> window_variances(const RawLog& log, const std::vector<char>& usable, int w, const Vec3& shift);
// Each axis' variance over a window of w samples from their (shifted) sum and sum of squares (rounding
// below 0 taken as 0), and the norm of the three, which the detection compares with its floor.
Vec3 window_axis_variances(const Vec3& sum, const Vec3& sum2, int w);
double window_variance_norm(const Vec3& sum, const Vec3& sum2, int w);

// The whole log as one last chunk of the stream's detection (pose_stream.hpp). Throws InputError
// (the log's file) when the log is shorter than the window, when the still period (still_seconds > 0)
// is, or when no window has any noise (a constant or clipped signal).
IntervalDetection detect_static_intervals(const RawLog& log, const StaticIntervalOptions& options = {});

}  // namespace scalcal
