// The measurement model of a vector meter, eq. (2): I_meas = Delta + (E + dK) Phi I + omega, with
// the rows of Phi the sensitivity axes of the three sensors in the meter's frame. Used both to
// simulate a meter (with noise and bench errors) and, inverted, to compensate measurements.
#pragma once
#include <cmath>
#include <cstdint>

#include <Eigen/Dense>

#include "numeric/model/paper9.hpp"
#include "numeric/program/random_sphere.hpp"

namespace scalcal {

// Sign convention (eq. 2): row k of Phi is sensor k's axis, so Phi(x, y) = phi_xy is how much of
// I_y sensor x sees. The diagonal sqrt(1 - phi_k.^2) keeps every axis a unit vector, so the
// scale factor of sensor k is exactly 1 + dk_k. Scalar calibration sees only the cosines between
// axes, gamma_kj = phi_kj + phi_jk to first order; the rotation part (phi_kj - phi_jk) / 2 moves
// the whole triad rigidly and leaves every modulus unchanged.
template <class Scalar>
struct MeterTpl {
  Vec3T<Scalar> bias = Vec3T<Scalar>::Zero();             // Delta, in the units of I
  Vec3T<Scalar> scale_deviation = Vec3T<Scalar>::Zero();  // dk_x, dk_y, dk_z
  Mat3T<Scalar> misalignment = Mat3T<Scalar>::Zero();     // phi_kj off the diagonal; diagonal unused

  Mat3T<Scalar> phi() const {
    using std::sqrt;
    Mat3T<Scalar> P = misalignment;
    for (int k = 0; k < 3; ++k) {
      Scalar off(0);
      for (int j = 0; j < 3; ++j)
        if (j != k) off += P(k, j) * P(k, j);
      P(k, k) = sqrt(Scalar(1) - off);
    }
    return P;
  }

  // (E + dK) Phi: the linear part of eq. (2).
  Mat3T<Scalar> gain() const { return (Vec3T<Scalar>::Ones() + scale_deviation).asDiagonal() * phi(); }

  Vec3T<Scalar> measure(const Vec3T<Scalar>& I) const { return bias + gain() * I; }

  // The inverse of the noise-free model: the vector that would have produced `measured`.
  Vec3T<Scalar> compensate(const Vec3T<Scalar>& measured) const { return gain().inverse() * (measured - bias); }

  // gamma = (phi_xy + phi_yx, phi_yz + phi_zy, phi_zx + phi_xz): order xy, yz, zx.
  Vec3T<Scalar> nonorthogonality() const {
    const Mat3T<Scalar>& p = misalignment;
    return Vec3T<Scalar>(p(0, 1) + p(1, 0), p(1, 2) + p(2, 1), p(2, 0) + p(0, 2));
  }

  // The paper's X (eq. 5): (Delta / |I|, dk, gamma).
  Vec9T<Scalar> parameters(const Scalar& magnitude) const {
    Vec9T<Scalar> X;
    X << bias / magnitude, scale_deviation, nonorthogonality();
    return X;
  }

  // The meter an estimate X stands for. The rotation part is not identifiable, so it is set to
  // zero: phi_kj = phi_jk = gamma_kj / 2.
  static MeterTpl from_parameters(const Vec9T<Scalar>& X, const Scalar& magnitude) {
    MeterTpl m;
    m.bias = X.template segment<3>(0) * magnitude;
    m.scale_deviation = X.template segment<3>(3);
    const Scalar half(0.5);
    const int pairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    for (int q = 0; q < 3; ++q) {
      m.misalignment(pairs[q][0], pairs[q][1]) = half * X(6 + q);
      m.misalignment(pairs[q][1], pairs[q][0]) = half * X(6 + q);
    }
    return m;
  }
};

using Meter = MeterTpl<double>;

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
