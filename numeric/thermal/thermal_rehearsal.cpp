// Simulated thermal logs (thermal_rehearsal.hpp).
#include "numeric/thermal/thermal_rehearsal.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "numeric/calibration/meter_model.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal {
namespace {

// The unit vector a fraction s of the way from a to b along their great circle.
Eigen::Vector3d slerp(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double s) {
  const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
  if (angle < 1e-9) return a;
  Eigen::Vector3d axis = a.cross(b);
  if (axis.norm() < 1e-12) axis = a.unitOrthogonal();  // antipodes: any great circle
  axis.normalize();
  const double t = s * angle;
  return std::cos(t) * a + std::sin(t) * axis.cross(a);
}

// 20 degrees away from a, perpendicular to it: where the meter swings between two close rows.
Eigen::Vector3d aside(const Eigen::Vector3d& a) {
  const double t = 20 * M_PI / 180;
  return std::cos(t) * a + std::sin(t) * a.unitOrthogonal();
}

}  // namespace

double thermal_rehearsal_samples(const ThermalRehearsalRequest& q) {
  const double per_row = q.dwell_s + 2 + 180.0 / 45;  // a rest and the longest move, with a swing
  const double seconds = q.ramp_c_per_min > 0 ? 60 * (q.range.high - q.range.low) / q.ramp_c_per_min + per_row
                                              : static_cast<double>(q.program.size()) * per_row;
  return seconds * q.rate_hz;
}

ThermalRehearsal rehearse_thermal(const ThermalRehearsalRequest& q) {
  if (!model_supports(q.model.base, ModelCapability::thermal_base))
    throw std::invalid_argument("a thermal rehearsal simulates " + calibrated_thermal_models() + " (got " +
                                q.model.name() + ")");
  if (!(q.rate_hz >= 1e-3 && q.rate_hz <= 1e6)) throw std::invalid_argument("the rate must be within 1e-3..1e6 Hz");
  const bool ramp = q.ramp_c_per_min > 0;
  if (thermal_rehearsal_samples(q) > kMaxThermalRehearsalSamples)
    throw std::invalid_argument(ramp ? "the ramp's log would have more than 2e7 samples: a faster ramp or a lower rate"
                                     : words("the log would have more than 2e7 samples: lower {rate} or {dwell}"));
  ThermalRehearsal r;
  GaussianSource gauss(q.seed);
  r.truth.resize(q.model.parameters());
  for (Eigen::Index i = 0; i < r.truth.size(); ++i)
    r.truth(i) = (i < q.model.base_parameters() ? q.size : q.drift) * gauss();
  auto emit = [&](const Eigen::Vector3d& eta, double planned, int row) {
    const double celsius =
        ramp ? std::min(q.range.high, q.range.low + q.ramp_c_per_min * static_cast<double>(r.t.size()) / q.rate_hz / 60)
             : planned;
    const Meter meter = q.model.meter_at(r.truth, q.range.tau(celsius), q.magnitude);
    Eigen::Vector3d w = meter.measure(q.magnitude * eta);
    for (int c = 0; c < 3; ++c) w(c) += q.noise * q.magnitude * gauss();
    r.t.push_back(static_cast<double>(r.t.size()) / q.rate_hz);
    r.celsius.push_back(celsius);
    r.samples.push_back(w);
    r.row.push_back(row);
  };
  auto move = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, double ca, double cb) {
    const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180 / M_PI;
    const int n = static_cast<int>(std::ceil(std::max(1.0, angle / 45) * q.rate_hz));
    for (int i = 1; i <= n; ++i) {
      const double s = (1 - std::cos(M_PI * i / n)) / 2;
      emit(slerp(a, b, s), ca + (cb - ca) * s, 0);
    }
  };
  const int rest = std::max(1, static_cast<int>(std::lround(q.dwell_s * q.rate_hz)));
  const int n = q.program.size();
  // Set-points: each row once. A ramp: the rows over and over until the temperature has reached T2.
  for (int k = 0; ramp ? (r.celsius.empty() || r.celsius.back() < q.range.high) : k < n; ++k) {
    const int i = k % n;
    const Eigen::Vector3d& e = q.program.positions[static_cast<std::size_t>(i)];
    const double c = q.program.celsius[static_cast<std::size_t>(i)];
    if (k > 0) {
      const int before = (k - 1) % n;
      const Eigen::Vector3d& prev = q.program.positions[static_cast<std::size_t>(before)];
      const double pc = q.program.celsius[static_cast<std::size_t>(before)];
      if (std::acos(std::clamp(prev.dot(e), -1.0, 1.0)) < 5 * M_PI / 180) {
        move(prev, aside(prev), pc, (pc + c) / 2);
        move(aside(prev), e, (pc + c) / 2, c);
      } else {
        move(prev, e, pc, c);
      }
    }
    for (int s = 0; s < rest; ++s) emit(e, c, i + 1);
  }
  return r;
}

}  // namespace scalcal
