// The moving variance of one window length over a log stream and the noise floor taken from it: what
// every still-pose detector of that window needs, computed once and shared (calibrate's adaptive
// choice runs 37 detectors over 4 windows; each holding its own copy took 16 bytes per sample each).
#pragma once
#include <cstddef>
#include <vector>

#include "numeric/calibration/log_stream.hpp"

namespace scalcal {

// White windows seen before a stream's floor is trusted, in windows: one window's worth of windows
// (a still stretch of two windows' length).
inline constexpr int kFloorWhiteWindows = 1;

class MovingVariance {
 public:
  // `quiet_floor`: keep the quiet windows' floor up to date (a detector whose floor is an initial still
  // period, --still, does not need it).
  MovingVariance(double window_seconds, bool quiet_floor);
  // Takes what the stream's samples decided so far allow. Idempotent: the detectors sharing it each call
  // it after every chunk, and only the first call does anything.
  void advance(const LogStream& stream);

  double window_seconds() const { return window_seconds_; }
  bool quiet_floor() const { return quiet_floor_; }
  int window() const { return window_; }  // samples; 0 until the stream's period is fixed
  // Per sample as far as computed: the window's variance norm, NaN for an incomplete window or one
  // holding an unusable sample.
  const std::vector<double>& variances() const { return variances_; }
  bool any_complete_window() const { return !finite_.empty(); }
  // The median of the quiet windows (static_intervals.hpp's rule) as last trusted; 0 before.
  double floor() const { return floor_; }

 private:
  bool fix_window(const LogStream& stream);
  void extend(const LogStream& stream);
  void update_floor(const LogStream& stream);

  double window_seconds_;
  bool quiet_floor_;
  int window_ = 0;
  std::vector<double> variances_;
  std::vector<double> finite_;     // the finite ones, in order: the floor's data
  std::size_t floor_windows_ = 0;  // finite_.size() when the floor was last computed
  int white_ = 0;                  // white windows seen
  double floor_ = 0;
};

}  // namespace scalcal
