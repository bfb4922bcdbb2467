// Simulating a vector meter of eq. (2) (numeric/model/meter.hpp) on a bench: its noise omega as seeded Gaussian
// deviates, and a bench error as a tilt of the position.
#pragma once
#include <cmath>
#include <cstdint>

#include <Eigen/Dense>

#include "numeric/model/meter.hpp"
#include "numeric/model/paper9.hpp"
#include "numeric/program/random_sphere.hpp"

namespace scalcal {

// Seeded Gaussian deviates from the bit-specified SphereSampler engine (Box-Muller written out,
// since std::normal_distribution differs between standard libraries).
class GaussianSource {
 public:
  explicit GaussianSource(std::uint64_t seed) : sampler_(seed) {}
  double operator()() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - sampler_.uniform();  // (0, 1]
    const double u2 = sampler_.uniform();
    const double r = std::sqrt(-2.0 * std::log(u1));
    spare_ = r * std::sin(2.0 * M_PI * u2);
    has_spare_ = true;
    return r * std::cos(2.0 * M_PI * u2);
  }
  SphereSampler& sampler() { return sampler_; }

 private:
  SphereSampler sampler_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

// A bench error: the meter actually sits at `eta` tipped by `angle_rad` towards a uniformly
// random direction perpendicular to eta.
inline Vec3 tilt(const Vec3& eta, double angle_rad, SphereSampler& sampler) {
  Vec3 t;
  do {
    t = sampler();
    t -= t.dot(eta) * eta;
  } while (t.norm() < 1e-6);
  t.normalize();
  return std::cos(angle_rad) * eta + std::sin(angle_rad) * t;
}

}  // namespace scalcal
