// Still-pose detection as a stream: a log taken in chunks as a logger delivers it, each sample
// judged once, when what its decision needs has arrived, and never judged again. The rules are
// static_intervals.hpp's; what they take from the whole log they take from the log so far: the
// noise floor (the median of the quiet windows) from the windows seen, the sample period from the
// steps seen, the saturation rails from the extremes seen, the field's radius from the spread
// seen. So the whole log given as one last chunk is the batch detection, decision for decision
// (detect_static_intervals is exactly that), and a log given in small chunks decides each sample
// with less knowledge: until the windows whose variance is white noise, not smooth motion (as the C
// library's detector judges), make up the 5 % of the windows the floor's quantile starts from, it
// decides nothing, so a log that starts in slow motion does not take that motion for the floor.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "numeric/calibration/log_stream.hpp"
#include "numeric/calibration/moving_variance.hpp"
#include "numeric/calibration/static_intervals.hpp"

namespace scalcal {

// The still poses of one set of options, judged as the log stream's samples are decided.
class StillPoseDetector {
 public:
  // `windows`: the moving variance of the options' window, shared with other detectors of that window
  // (null: its own).
  explicit StillPoseDetector(StaticIntervalOptions options, std::shared_ptr<MovingVariance> windows = nullptr);
  // Judges what the stream's samples decided so far allow (everything once the stream ended).
  void advance(const LogStream& stream);
  // The poses judged so far. Once the stream has ended it throws InputError where the batch
  // detection does (no usable sample, no complete window, a still period too short, no noise).
  IntervalDetection detection(const LogStream& stream) const;
  const StaticIntervalOptions& options() const { return options_; }

 private:
  bool settle_still_period(const LogStream& stream);
  bool update_floor(const LogStream& stream);
  void judge(const LogStream& stream, int upto);
  void close_run(const LogStream& stream);
  void settle_pending(const LogStream& stream);

  StaticIntervalOptions options_;
  std::shared_ptr<MovingVariance> windows_;
  double floor_ = 0, threshold_ = 0;
  bool floor_from_still_ = false;
  bool still_settled_ = false;  // --still: the period is past (still_samples_ usable samples in it)
  int still_samples_ = 0;
  int judged_ = 0;                          // samples judged static or not
  std::optional<std::pair<int, int>> run_;  // the open still run
  std::optional<StaticInterval> pending_;   // the last merged run, which a run a short break later may join
  int pending_last_begin_ = 0;              // the last run merged into it
  std::vector<StaticInterval> intervals_;
  int short_runs_ = 0, drifting_runs_ = 0, longest_samples_ = 0;
};

}  // namespace scalcal
