// The meter of eq. (2) as a value: I_meas = Delta + (E + dK) Phi I, with the rows of Phi the sensitivity axes of
// the three sensors in the meter's frame; below the calibration, so that a model can name the meter it estimates.
#pragma once
#include <cmath>

#include <Eigen/Dense>

#include "numeric/model/model.hpp"

namespace scalcal {

template <class Scalar>
using Vec9T = Eigen::Matrix<Scalar, 9, 1>;

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

}  // namespace scalcal
