// A gyro's log split into rests and constant-rate segments (a rate table), or into rests and the
// turns between them (known turns). A constant rate is, to the output, what a still pose is to an
// accelerometer: a run of samples whose variance stays at the noise floor, so the static-interval
// detector finds both (numeric/calibration/static_intervals.hpp). Rests are the intervals whose mean
// outputs coincide (the bias, whatever the rate of the others): intervals are linked when their means
// differ by less than kRestSigmas standard errors of the difference (plus the rests' own spread,
// a MEMS gyro's bias moving with time and attitude), and the largest linked group of at least two is
// the rests; every other interval is a segment. A log without two coinciding intervals has no rests.
#pragma once
#include <vector>

#include "numeric/calibration/raw_log.hpp"
#include "numeric/calibration/static_intervals.hpp"

namespace scalcal::gyro {

inline constexpr double kRestSigmas = 30;

struct LogInterval {
  StaticInterval span;
  Vec3 mean = Vec3::Zero();  // raw units
  Vec3 sd = Vec3::Zero();    // one sample's standard deviation per axis
  int samples = 0;           // finite samples used
  int line = 0;              // first line in the file
};

struct RateLogSegments {
  IntervalDetection detection;
  std::vector<LogInterval> rests;     // in time order
  std::vector<LogInterval> segments;  // constant-rate segments, in time order
};

// Mean and scatter of the finite samples begin..end.
LogInterval summarise(const RawLog& log, int begin, int end);

// Throws InputError as detect_static_intervals does.
RateLogSegments segment_rate_log(const RawLog& log, const StaticIntervalOptions& options = {});

// A turn: from the end of one rest to the start of the next (a rest ends where the moving window
// centred on it still holds no motion, so the whole motion is inside), as IMU-TK integrates between
// poses; the few rest samples inside add the bias times their duration, which the calibration models.
// Longer spans would add the bias's wander over the rests (imucal's Ferraris session: 2e-4 of a turn).
struct Turn {
  int begin = 0, end = 0;        // sample indices, inclusive
  Vec3 integral = Vec3::Zero();  // sum of raw (w_i + w_i+1) dt_i / 2: raw units x seconds
  double seconds = 0;
  int line = 0;
};

// Turns between consecutive rests, skipping pairs of rests with no motion between them (their means
// and the samples between stay within the rests' noise).
std::vector<Turn> turns_between_rests(const RawLog& log, const RateLogSegments& segments);

// The known turns among the motions between rests: a turn protocol also moves the meter between
// faces (imucal's Ferraris session), by a quarter or half turn, and the known turns (whole turns
// each) are the largest motions. Kept: the motions whose integrated output less the rests' mean
// over their duration is within kLargestTurn of the largest's (a full turn is twice any face change;
// the gain's anisotropy moves a whole turn's integral by a few per cent).
inline constexpr double kLargestTurn = 0.25;
std::vector<Turn> largest_turns(const std::vector<Turn>& turns, const Vec3& rest_mean);

}  // namespace scalcal::gyro
