// A raw log taken in chunks as a logger delivers it, and what its samples are whatever the
// detection's options: usable or not (finite, not saturated at a rail), the sample period, and the
// running sums the windows' variances are taken from. Each sample is decided once, when the two
// samples after it (which a saturated run of three needs) have arrived, from the extremes seen so
// far; the whole log as one last chunk decides every sample as the batch detection does.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "numeric/calibration/raw_log.hpp"
#include "numeric/calibration/static_intervals.hpp"

namespace scalcal {

// What does not depend on the detection's options: the log so far, which samples are usable
// (finite, not saturated), the sample period, and running sums for the windows' variances.
class LogStream {
 public:
  explicit LogStream(std::string file);
  // Appends a chunk's rows (times increasing from the last chunk's); `last`: the log ends here.
  // Throws InputError for time that does not increase across chunks and for overflowing values.
  void add(const RawLog& chunk, bool last);
  void add(RawLog&& chunk, bool last);  // the same; a first chunk becomes the log without a copy

  const RawLog& log() const { return log_; }
  RawLog release() &&;  // the log, for a caller done with the stream
  bool ended() const { return ended_; }
  // Samples whose usability is decided (a saturated run needs two samples after it).
  int decided() const { return static_cast<int>(usable_.size()); }
  const std::vector<char>& usable() const { return usable_; }
  // The median step between finite samples, fixed when the log ends or has a window's span
  // (window_seconds) at the period seen so far; 0 before.
  double period_for(double window_seconds) const;
  // The period once fixed (0 before): asking never fixes it.
  double period() const { return period_.value_or(0.0); }
  int first_usable() const { return first_usable_; }
  // The variance norm over usable samples [i - h, i + h] (NaN for an unusable one or an incomplete window);
  // needs i + h < decided().
  double window_variance(int i, int h) const;
  // Whether that window is white noise: its mean squared step at least half its variance (a
  // smooth motion's steps are far smaller than its spread).
  bool window_white(int i, int h) const;
  // Half the spread of the usable outputs decided so far, the median over the three.
  double field_radius() const;
  // The counts and first lines of unusable rows, as IntervalDetection holds them.
  void describe(IntervalDetection& d) const;

 private:
  void take_rows(int from, bool last);
  void decide_usable(int upto);
  bool saturated(int k) const;

  RawLog log_;
  bool ended_ = false;
  std::vector<char> usable_;
  Vec3 finite_lo_, finite_hi_, usable_lo_, usable_hi_;
  std::vector<double> steps_;
  mutable std::optional<double> period_;
  int previous_finite_ = -1, first_usable_ = -1;
  int nonfinite_ = 0, saturated_ = 0;
  std::vector<int> nonfinite_lines_, saturated_lines_;
  double largest_ = 0;
  // Prefix sums of the usable samples less the first usable one (raw sums of counts near 32768
  // would cancel badly), of their squares, of unusable samples, and of squared steps between
  // consecutive usable samples.
  std::vector<Vec3> ps_, ps2_;
  std::vector<int> bad_;
  std::vector<double> steps2_;
};

}  // namespace scalcal
