// Rests, constant-rate segments and turns in a gyro's log (rate_segments.hpp).
#include "numeric/gyro/rate_segments.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace scalcal::gyro {

LogInterval summarise(const RawLog& log, int begin, int end) {
  LogInterval out;
  out.span.begin = begin;
  out.span.end = end;
  out.span.start = log.t[static_cast<std::size_t>(begin)];
  out.span.stop = log.t[static_cast<std::size_t>(end)];
  out.line = log.lines[static_cast<std::size_t>(begin)];
  Vec3 s = Vec3::Zero();
  for (int i = begin; i <= end; ++i)
    if (log.finite(i)) s += log.samples[static_cast<std::size_t>(i)], ++out.samples;
  if (out.samples == 0) return out;
  out.mean = s / out.samples;
  Vec3 ss = Vec3::Zero();
  for (int i = begin; i <= end; ++i)
    if (log.finite(i)) ss += (log.samples[static_cast<std::size_t>(i)] - out.mean).cwiseAbs2();
  out.sd = (ss / std::max(1, out.samples - 1)).cwiseSqrt();
  return out;
}

namespace {

// Union-find over the intervals: linked when their means coincide within the noise.
int root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i)
    i = parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
  return i;
}

bool coincide(const LogInterval& a, const LogInterval& b) {
  // Standard error of the difference of the means, per axis, from each interval's own scatter; the
  // noise of a sample stands in for the slow wander of a bias (the threshold is generous: a rate
  // of the table differs from rest by thousands of these).
  for (int c = 0; c < 3; ++c) {
    const double se = std::sqrt(a.sd(c) * a.sd(c) / a.samples + b.sd(c) * b.sd(c) / b.samples);
    const double floor = 0.5 * std::min(a.sd(c), b.sd(c));
    if (std::abs(a.mean(c) - b.mean(c)) > kRestSigmas * se + floor) return false;
  }
  return true;
}

}  // namespace

RateLogSegments segment_rate_log(const RawLog& log, const StaticIntervalOptions& options) {
  RateLogSegments out;
  out.detection = detect_static_intervals(log, options);
  std::vector<LogInterval> all;
  for (const auto& iv : out.detection.intervals) all.push_back(summarise(log, iv.begin, iv.end));
  const int n = static_cast<int>(all.size());
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (coincide(all[static_cast<std::size_t>(i)], all[static_cast<std::size_t>(j)]))
        parent[static_cast<std::size_t>(root(parent, i))] = root(parent, j);
  std::vector<int> size(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) ++size[static_cast<std::size_t>(root(parent, i))];
  int best = -1;
  for (int i = 0; i < n; ++i)  // the largest group; ties go to the earliest (deterministic)
    if (size[static_cast<std::size_t>(i)] >= 2 &&
        (best < 0 || size[static_cast<std::size_t>(i)] > size[static_cast<std::size_t>(best)]))
      best = i;
  for (int i = 0; i < n; ++i)
    (best >= 0 && root(parent, i) == best ? out.rests : out.segments).push_back(all[static_cast<std::size_t>(i)]);
  return out;
}

std::vector<Turn> turns_between_rests(const RawLog& log, const RateLogSegments& s) {
  std::vector<Turn> out;
  for (std::size_t k = 0; k + 1 < s.rests.size(); ++k) {
    const LogInterval &a = s.rests[k], &b = s.rests[k + 1];
    Turn turn;
    turn.begin = a.span.end;
    turn.end = b.span.begin;
    turn.line = log.lines[static_cast<std::size_t>(turn.begin)];
    const Vec3 rest = 0.5 * (a.mean + b.mean);
    Vec3 moved = Vec3::Zero();
    int between = 0;
    for (int i = turn.begin; i < turn.end; ++i) {
      if (!log.finite(i) || !log.finite(i + 1)) continue;
      const double dt = log.t[static_cast<std::size_t>(i) + 1] - log.t[static_cast<std::size_t>(i)];
      const Vec3 w = 0.5 * (log.samples[static_cast<std::size_t>(i)] + log.samples[static_cast<std::size_t>(i) + 1]);
      turn.integral += w * dt;
      moved += (w - rest) * dt;
      turn.seconds += dt;
      ++between;
    }
    // No motion between the two rests (one rest split in two): its integral is the rests' noise.
    const double dt = between > 0 ? turn.seconds / between : 0;
    const double noise = 0.5 * (a.sd.norm() + b.sd.norm()) * dt * std::sqrt(static_cast<double>(between));
    if (between > 0 && moved.norm() > kRestSigmas * noise) out.push_back(turn);
  }
  return out;
}

std::vector<Turn> largest_turns(const std::vector<Turn>& turns, const Vec3& rest_mean) {
  double largest = 0;
  for (const Turn& t : turns) largest = std::max(largest, (t.integral - t.seconds * rest_mean).norm());
  std::vector<Turn> out;
  for (const Turn& t : turns)
    if ((t.integral - t.seconds * rest_mean).norm() >= (1 - kLargestTurn) * largest) out.push_back(t);
  return out;
}

}  // namespace scalcal::gyro
