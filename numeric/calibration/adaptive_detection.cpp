// The still-pose detection chosen per log (adaptive_detection.hpp).
#include "numeric/calibration/adaptive_detection.hpp"

#include <cmath>

#include "numeric/io/input_error.hpp"

namespace scalcal {

std::vector<PositionSamples> interval_positions(const RawLog& log, const IntervalDetection& d) {
  std::vector<PositionSamples> out;
  for (const auto& iv : d.intervals) {
    PositionSamples p;
    p.line = log.lines[static_cast<std::size_t>(iv.begin)];
    for (int i = iv.begin; i <= iv.end; ++i) {
      if (!log.finite(i) || iv.in_break(i)) continue;
      p.samples.push_back(log.samples[static_cast<std::size_t>(i)]);
      p.sample_lines.push_back(log.lines[static_cast<std::size_t>(i)]);
    }
    out.push_back(std::move(p));
  }
  return out;
}

std::vector<StaticIntervalOptions> detection_candidates(const StaticIntervalOptions& base) {
  std::vector<StaticIntervalOptions> out{base};
  StaticIntervalOptions o = base;
  for (double window : kDetectionWindows)
    for (double threshold : kDetectionThresholds)
      for (double shortest : kDetectionShortest) {
        o.window_seconds = window;
        o.threshold_factor = threshold;
        o.min_seconds = shortest;
        out.push_back(o);
      }
  return out;
}

std::optional<DetectionChoice> choose_detection(
    const std::function<IntervalDetection(const StaticIntervalOptions&, int)>& detect,
    const StaticIntervalOptions& base, const std::function<std::optional<double>(const IntervalDetection&)>& score) {
  std::optional<DetectionChoice> best;
  int scored = 0;
  const auto try_options = [&](const StaticIntervalOptions& o, int k, int* positions) -> std::optional<double> {
    IntervalDetection d;
    try {
      d = detect(o, k);
    } catch (const InputError&) {  // a window longer than the log, say
      return std::nullopt;
    }
    if (positions) *positions = static_cast<int>(d.intervals.size());
    const auto s = score(d);
    if (!s || !std::isfinite(*s)) return std::nullopt;
    ++scored;
    if (!best || *s < best->score * (1 - 1e-9)) {
      if (!best) best.emplace();
      best->options = o;
      best->detection = std::move(d);
      best->score = *s;
    }
    return s;
  };
  // The defaults first: they are what the choice is measured against.
  const std::vector<StaticIntervalOptions> candidates = detection_candidates(base);
  int default_positions = 0;
  const auto first = try_options(candidates[0], 0, &default_positions);
  for (std::size_t k = 1; k < candidates.size(); ++k) try_options(candidates[k], static_cast<int>(k), nullptr);
  if (best) {
    best->default_score = first ? *first : NAN;
    best->default_positions = default_positions;
    best->scored = scored;
  }
  return best;
}

std::optional<DetectionChoice> choose_detection(
    const RawLog& log, const StaticIntervalOptions& base,
    const std::function<std::optional<double>(const IntervalDetection&)>& score) {
  return choose_detection([&](const StaticIntervalOptions& o, int) { return detect_static_intervals(log, o); }, base,
                          score);
}

}  // namespace scalcal
