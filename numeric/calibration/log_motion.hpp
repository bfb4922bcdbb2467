// How a raw log moves, judged from the log alone: the white noise of one sample (from second
// differences, which slow motion hardly enters: a smooth rotation adds its second derivative times
// dt^2), the share of the log in motion, and whether the measured modulus survives the motion. A
// magnetometer's does (the field is the same however the meter turns), so every sample of a
// tumbling log is a position; an accelerometer's does not (motion adds acceleration), so only its
// still poses are. The modulus is judged on the ellipsoid through all usable samples: in motion,
// its robust deviation within kSurvivingNoise times the per-sample noise is a field that survives.
#pragma once
#include <string>

#include "numeric/calibration/raw_log.hpp"
#include "numeric/calibration/static_intervals.hpp"

namespace scalcal {

// A modulus that moves by up to this many times one sample's noise while the meter moves survives
// the motion: a hand-moved accelerometer's moves by 10-50 times (0.05-0.2 g against 0.002-0.01 g of
// noise); a magnetometer's stays within 1-2 (the public QMC5883L log: 1.4).
inline constexpr double kSurvivingNoise = 4;
// A log more in motion than this share is a candidate tumbling log (hand-held still-pose logs move
// for 30-40 % of their time; the public magnetometer log for 80 %).
inline constexpr double kMovingShare = 0.5;
// A window moves when its variance norm exceeds this many times one sample's white noise (the
// public logs' still windows: 0.6-1.1 times; a window of w samples fluctuates by about sqrt(2 / w)).
inline constexpr double kMovingWindow = 3;

struct LogMotion {
  Vec3 noise = Vec3::Zero();      // one sample's white noise per output, raw units (second differences)
  double moving_share = 0;        // usable samples whose window varies beyond kMovingWindow times the noise
  double noise_relative = NAN;    // one sample's noise on the modulus, relative to it
  double moving_deviation = NAN;  // robust RMS of |corrected| / radius - 1 over moving samples (relative)
  double still_deviation = NAN;   // the same over still samples
  bool ellipsoid = false;         // an ellipsoid passes through the samples (else the two deviations are NaN)
  // The modulus keeps within kSurvivingNoise times the noise in motion (and the log moves at all).
  bool field_survives() const { return ellipsoid && moving_deviation <= kSurvivingNoise * noise_relative; }
  bool mostly_moving() const { return moving_share > kMovingShare; }
};

// One sample's white noise per output, from the median absolute second difference (robust to the
// motion's few large steps): a second difference of white noise has variance 6 sigma^2.
Vec3 second_difference_noise(const RawLog& log, const std::vector<char>& usable);

LogMotion judge_motion(const RawLog& log, const IntervalDetection& detection);

// One line on how the log moves, for the report.
std::string motion_text(const LogMotion& motion);

}  // namespace scalcal
