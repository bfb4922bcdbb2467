// Seeded uniform sampling on the unit sphere, bit-reproducible across platforms: mt19937_64 is
// fully specified by the standard, and the mapping to the sphere (Archimedes: z uniform in
// [-1, 1], azimuth uniform) is written out here rather than left to std::distributions.
#pragma once
#include <cmath>
#include <cstdint>
#include <random>

#include "numeric/model/paper9.hpp"

namespace scalcal {

class SphereSampler {
 public:
  explicit SphereSampler(std::uint64_t seed) : engine_(seed) {}

  // Uniform double in [0, 1) from the top 53 bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  Vec3 operator()() {
    const double z = 2.0 * uniform() - 1.0;
    const double phi = 2.0 * M_PI * uniform();
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
  }

  std::mt19937_64& engine() { return engine_; }

 private:
  std::mt19937_64 engine_;
};

}  // namespace scalcal
