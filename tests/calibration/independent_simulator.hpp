// A bench simulator written for the tests only, apart from numeric/meter_model.hpp: eq. (2)
// component by component with plain arrays, its own generator and its own classic18 program.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace calibration_test {

using V3 = std::array<double, 3>;

struct TrueMeter {
  V3 bias{};              // Delta, units of I
  V3 dk{};                // scale-factor deviations
  double phi[3][3] = {};  // phi_kj for k != j; row k = sensor k's axis (eq. 2)

  // gamma_xy, gamma_yz, gamma_zx = phi_kj + phi_jk
  V3 gamma() const { return {phi[0][1] + phi[1][0], phi[1][2] + phi[2][1], phi[2][0] + phi[0][2]}; }

  V3 measure(const V3& I) const {
    V3 out{};
    for (int k = 0; k < 3; ++k) {
      double off2 = 0, dot = 0;
      for (int j = 0; j < 3; ++j)
        if (j != k) {
          off2 += phi[k][j] * phi[k][j];
          dot += phi[k][j] * I[j];
        }
      dot += std::sqrt(1.0 - off2) * I[k];
      out[k] = bias[k] + (1.0 + dk[k]) * dot;
    }
    return out;
  }
};

// A meter with errors of about `s`, including a rotation part (phi_xy != phi_yx).
inline TrueMeter example_meter(double s, double magnitude) {
  TrueMeter m;
  m.bias = {1.3 * s * magnitude, -0.7 * s * magnitude, 0.4 * s * magnitude};
  m.dk = {-0.9 * s, 0.5 * s, 1.1 * s};
  m.phi[0][1] = 0.8 * s;
  m.phi[1][0] = -0.2 * s;
  m.phi[1][2] = 0.3 * s;
  m.phi[2][1] = 0.6 * s;
  m.phi[2][0] = -0.5 * s;
  m.phi[0][2] = -0.4 * s;
  return m;
}

// The 18 positions of Fig. 1 written out: +-each axis, and the four 45-degree directions in each
// coordinate plane.
inline std::vector<V3> classic18_positions() {
  std::vector<V3> p;
  for (int a = 0; a < 3; ++a)
    for (double s : {1.0, -1.0}) {
      V3 v{0, 0, 0};
      v[a] = s;
      p.push_back(v);
    }
  const double c = 1.0 / std::sqrt(2.0);
  for (int a = 0; a < 3; ++a)
    for (double s1 : {1.0, -1.0})
      for (double s2 : {1.0, -1.0}) {
        V3 v{0, 0, 0};
        v[a] = s1 * c;
        v[(a + 1) % 3] = s2 * c;
        p.push_back(v);
      }
  return p;
}

class Noise {
 public:
  explicit Noise(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return (static_cast<double>(engine_() >> 11) + 0.5) * 0x1.0p-53; }
  double gauss() {  // Marsaglia's polar method
    double u, v, s;
    do {
      u = 2 * uniform() - 1;
      v = 2 * uniform() - 1;
      s = u * u + v * v;
    } while (s >= 1 || s == 0);
    return u * std::sqrt(-2 * std::log(s) / s);
  }

 private:
  std::mt19937_64 engine_;
};

// eta tipped by `angle` radians towards a random direction perpendicular to it.
inline V3 tipped(const V3& eta, double angle, Noise& rng) {
  V3 t;
  double n;
  do {
    t = {rng.gauss(), rng.gauss(), rng.gauss()};
    const double d = t[0] * eta[0] + t[1] * eta[1] + t[2] * eta[2];
    for (int k = 0; k < 3; ++k) t[k] -= d * eta[k];
    n = std::sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
  } while (n < 1e-6);
  V3 out;
  for (int k = 0; k < 3; ++k) out[k] = std::cos(angle) * eta[k] + std::sin(angle) * t[k] / n;
  return out;
}

}  // namespace calibration_test
