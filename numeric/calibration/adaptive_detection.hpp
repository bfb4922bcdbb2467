// Still-pose detection that uses every usable pose: a hand-held log of many short poses (0.3-1 s)
// loses most of them to a 1 s window and a 1 s minimum, and a log with long poses loses nothing to a
// shorter window. So the window, the threshold and the shortest pose are chosen per log among
// kDetectionCandidates, by what matters: the candidate whose calibration has the smallest parameter
// errors predicted from the noise within poses (a threshold that lets motion into the poses widens
// that noise and pays for it), measured by the determinant of their covariance to the power 1/P,
// which no choice of units changes. The residuals between poses do not score: with a few degrees of
// freedom their scatter is itself random, and the candidate that happened to fit best would win.
#pragma once
#include <functional>
#include <optional>
#include <vector>

#include "numeric/calibration/raw_log.hpp"
#include "numeric/calibration/scalar_calibration.hpp"
#include "numeric/calibration/static_intervals.hpp"

namespace scalcal {

inline constexpr double kDetectionWindows[] = {0.2, 0.35, 0.5, 1.0};  // seconds
inline constexpr double kDetectionThresholds[] = {4, 6, 10};          // times the noise floor
inline constexpr double kDetectionShortest[] = {0.3, 0.5, 1.0};       // seconds
inline constexpr int kDetectionCandidates = 4 * 3 * 3;

// The positions of a detection: each interval's finite samples.
std::vector<PositionSamples> interval_positions(const RawLog& log, const IntervalDetection& detection);

struct DetectionChoice {
  StaticIntervalOptions options;
  IntervalDetection detection;
  double score = NAN;          // the chosen candidate's det(covariance)^(1/P)
  double default_score = NAN;  // the default options' (NaN: they give no calibration)
  int default_positions = 0;
  int scored = 0;  // candidates that gave a calibration
};

// score(detection): det(covariance)^(1/P) of the calibration its positions give, or empty when they
// give none. Candidates are tried in a fixed order and the lowest score wins (the first on a tie), so
// the choice never turns on the last bits of arithmetic. `base` gives --still and the defaults. Empty
// when no candidate scores.
std::optional<DetectionChoice> choose_detection(
    const RawLog& log, const StaticIntervalOptions& base,
    const std::function<std::optional<double>(const IntervalDetection&)>& score);
// The same over any detector: detect(options, k) gives candidate k's detection (k = 0: `base`, then the
// candidates in kDetectionWindows x kDetectionThresholds x kDetectionShortest order) or throws InputError.
std::optional<DetectionChoice> choose_detection(
    const std::function<IntervalDetection(const StaticIntervalOptions&, int)>& detect,
    const StaticIntervalOptions& base, const std::function<std::optional<double>(const IntervalDetection&)>& score);
// The candidates' options, base's --still kept: base first, then kDetectionCandidates more.
std::vector<StaticIntervalOptions> detection_candidates(const StaticIntervalOptions& base);

}  // namespace scalcal
