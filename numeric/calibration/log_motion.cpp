// How a raw log moves (log_motion.hpp).
#include "numeric/calibration/log_motion.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "numeric/calibration/full_correction.hpp"

namespace scalcal {
namespace {

double median_of(std::vector<double> v) {
  if (v.empty()) return NAN;
  const auto k = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// Robust RMS: 1.4826 times the median absolute value (deviations about the ellipsoid, centred at 0).
double robust_rms(const std::vector<double>& v) {
  std::vector<double> a;
  a.reserve(v.size());
  for (double x : v) a.push_back(std::abs(x));
  return 1.4826 * median_of(a);
}

}  // namespace

Vec3 second_difference_noise(const RawLog& log, const std::vector<char>& usable) {
  Vec3 out = Vec3::Constant(NAN);
  for (int c = 0; c < 3; ++c) {
    std::vector<double> d;
    for (int i = 1; i + 1 < log.size(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!usable[k - 1] || !usable[k] || !usable[k + 1]) continue;
      d.push_back(log.samples[k + 1](c) - 2 * log.samples[k](c) + log.samples[k - 1](c));
    }
    const double m = median_of(d);
    std::vector<double> a;
    a.reserve(d.size());
    for (double x : d) a.push_back(std::abs(x - m));
    out(c) = 1.4826 * median_of(a) / std::sqrt(6.0);
  }
  return out;
}

LogMotion judge_motion(const RawLog& log, const IntervalDetection& d) {
  LogMotion m;
  const int n = log.size();
  m.noise = second_difference_noise(log, d.usable);
  // Still: the sample's window varies no more than the white noise allows (judged against the noise
  // itself, not the quietest windows, which in a log that never stops are motion too).
  std::vector<char> still(static_cast<std::size_t>(n), 0);
  int first = 0;
  while (first < n && !d.usable[static_cast<std::size_t>(first)]) ++first;
  if (first == n || !m.noise.allFinite()) return m;
  const double white = m.noise.cwiseProduct(m.noise).norm();
  const std::vector<double> v = window_variances(log, d.usable, d.window, log.samples[static_cast<std::size_t>(first)]);
  for (int i = 0; i < n; ++i) {
    const double x = v[static_cast<std::size_t>(i)];
    still[static_cast<std::size_t>(i)] = std::isfinite(x) && x <= kMovingWindow * white;
  }
  std::vector<Vec3> samples;
  std::vector<char> is_still;
  for (int i = 0; i < n; ++i)
    if (d.usable[static_cast<std::size_t>(i)]) {
      samples.push_back(log.samples[static_cast<std::size_t>(i)]);
      is_still.push_back(still[static_cast<std::size_t>(i)]);
    }
  if (samples.empty()) return m;
  m.moving_share = 1 - static_cast<double>(std::count(is_still.begin(), is_still.end(), 1)) / samples.size();
  const auto e = fit_ellipsoid(samples, 1.0, EllipsoidShape::general);
  if (!e) return m;
  m.ellipsoid = true;
  // The radial part of one sample's noise on the unit sphere: trace(C S C^T) / 3 on average over
  // directions, S = diag(noise^2).
  const Mat3 CS = e->matrix * m.noise.asDiagonal();
  m.noise_relative = std::sqrt((CS * CS.transpose()).trace() / 3);
  std::vector<double> moving, at_rest;
  for (std::size_t k = 0; k < samples.size(); ++k)
    (is_still[k] ? at_rest : moving).push_back(e->apply(samples[k]).norm() - 1);
  m.moving_deviation = robust_rms(moving);
  m.still_deviation = robust_rms(at_rest);
  return m;
}

std::string motion_text(const LogMotion& m) {
  char s[240];
  std::snprintf(s, sizeof s,
                "%.0f %% of the log moves; in motion the modulus deviates by %.3g %% (robust RMS), %.3g times one "
                "sample's noise (%.3g %%, from second differences)",
                100 * m.moving_share, 100 * m.moving_deviation, m.moving_deviation / m.noise_relative,
                100 * m.noise_relative);
  return s;
}

}  // namespace scalcal
