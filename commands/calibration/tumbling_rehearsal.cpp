// A tumbling rehearsal log (tumbling_rehearsal.hpp).
#include "commands/calibration/tumbling_rehearsal.hpp"

#include <algorithm>
#include <cmath>

namespace scalcal::commands {
namespace {

// The field's direction in the meter's frame at each sample: constant angular speed along great
// circles through the waypoints.
std::vector<Vec3> tumbling_path(const std::vector<Vec3>& waypoints, double rate_hz, long samples) {
  std::vector<Vec3> out;
  out.reserve(static_cast<std::size_t>(samples));
  const double step = kTumbleDegPerS * M_PI / 180 / rate_hz;  // radians per sample
  std::size_t w = 0;
  Vec3 at = waypoints[0];
  while (static_cast<long>(out.size()) < samples) {
    const Vec3 next = waypoints[(w + 1) % waypoints.size()];
    Vec3 axis = at.cross(next);
    const double angle = std::atan2(axis.norm(), at.dot(next));
    if (axis.norm() < 1e-9) axis = at.unitOrthogonal();
    axis.normalize();
    const long n = std::max(1L, static_cast<long>(angle / step));
    for (long k = 0; k < n && static_cast<long>(out.size()) < samples; ++k)
      out.push_back(Eigen::AngleAxisd(static_cast<double>(k) * angle / n, axis) * at);
    at = next;
    ++w;
  }
  return out;
}

// Smooth random acceleration (three sinusoids of 0.3-2 Hz per axis), RMS `rms` per sample.
std::vector<Vec3> hand_acceleration(GaussianSource& gauss, double rate_hz, long samples, double rms) {
  double f[3][3], phase[3][3];
  for (auto& row : f)
    for (double& x : row) x = 0.3 + 1.7 * (0.5 + 0.5 * std::erf(gauss() / std::sqrt(2.0)));
  for (auto& row : phase)
    for (double& x : row) x = M_PI * gauss();
  std::vector<Vec3> out(static_cast<std::size_t>(samples));
  // Three unit sinusoids per axis have RMS sqrt(3/2); scaled to `rms` over the three axes together.
  const double a = rms / std::sqrt(3 * 1.5);
  for (long i = 0; i < samples; ++i) {
    const double t = static_cast<double>(i) / rate_hz;
    for (int c = 0; c < 3; ++c) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += std::sin(2 * M_PI * f[c][k] * t + phase[c][k]);
      out[static_cast<std::size_t>(i)](c) = a * s;
    }
  }
  return out;
}

}  // namespace

RehearsalResult rehearse_tumbling(const RehearsalRequest& q) {
  RehearsalResult r;
  r.request = q;
  GaussianSource gauss(q.seed);
  r.meter = rehearsal_meter(q, gauss);
  r.correction = correction_of(r.meter);
  const long samples = std::max(2L, std::lround(q.tumble_s * q.rate_hz));
  std::vector<Vec3> waypoints = q.program.positions;
  if (waypoints.size() < 2) {
    waypoints.clear();
    for (int k = 0; k < 64; ++k) waypoints.push_back(Vec3(gauss(), gauss(), gauss()).normalized());
  }
  const std::vector<Vec3> path = tumbling_path(waypoints, q.rate_hz, samples);
  const std::vector<Vec3> motion = q.accelerometer ? hand_acceleration(gauss, q.rate_hz, samples, kHandAcceleration)
                                                   : std::vector<Vec3>(static_cast<std::size_t>(samples), Vec3::Zero());
  // Disturbances: a bump of kDisturbanceSeconds at random times, in a random fixed direction.
  std::vector<std::pair<long, Vec3>> bumps;
  const long width = std::lround(kDisturbanceSeconds * q.rate_hz);
  for (int k = 0; k < q.disturbances && samples > width; ++k) {
    const double u = 0.5 + 0.5 * std::erf(gauss() / std::sqrt(2.0));
    const long start = static_cast<long>(u * static_cast<double>(samples - width));
    bumps.emplace_back(start, Vec3(gauss(), gauss(), gauss()).normalized());
    r.disturbed.emplace_back(static_cast<double>(start) / q.rate_hz, static_cast<double>(start + width) / q.rate_hz);
  }
  for (long i = 0; i < samples; ++i) {
    const auto k = static_cast<std::size_t>(i);
    Vec3 field = q.magnitude * (path[k] + motion[k]);
    for (const auto& [start, direction] : bumps)
      if (i >= start && i < start + width)
        field += kDisturbanceField * q.magnitude * std::sin(M_PI * static_cast<double>(i - start) / width) * direction;
    const Vec3 e(gauss(), gauss(), gauss());
    r.t.push_back(static_cast<double>(i) / q.rate_hz);
    r.samples.push_back(r.meter.measure(field) + q.noise * q.magnitude * e);
    r.position.push_back(0);
  }
  return r;
}

}  // namespace scalcal::commands
