// The forms a target stores a correction in (matrix_forms.hpp).
#include "numeric/export/matrix_forms.hpp"

#include "numeric/calibration/full_correction.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

namespace scalcal {

Mat3 symmetric_factor(const Mat3& C) {
  const Eigen::SelfAdjointEigenSolver<Mat3> e(C.transpose() * C);
  return e.eigenvectors() * e.eigenvalues().cwiseSqrt().asDiagonal() * e.eigenvectors().transpose();
}

std::optional<RotationTriangle> rotation_times_lower(const Mat3& C) {
  if (!(C.determinant() > 0)) return std::nullopt;
  // QR of C with its columns reversed, C P = Q R, gives C = (Q P)(P R P) with P R P lower triangular.
  Mat3 P = Mat3::Zero();
  P(0, 2) = P(1, 1) = P(2, 0) = 1;
  const Eigen::HouseholderQR<Mat3> qr(C * P);
  const Mat3 R = qr.matrixQR().triangularView<Eigen::Upper>();
  RotationTriangle f;
  f.rotation = Mat3(qr.householderQ()) * P;
  f.lower = P * R * P;
  const Vec3 sign = f.lower.diagonal().cwiseSign();
  f.lower = sign.asDiagonal() * f.lower;
  f.rotation = f.rotation * sign.asDiagonal();
  return f;
}

// atan2 of the sine (from the antisymmetric part) and the cosine: acos of the trace alone loses
// half the digits near 0 (1e-8 radians for a rotation of none).
double rotation_angle(const Mat3& R) {
  const Vec3 s(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1));
  return std::atan2(s.norm() / 2, (R.trace() - 1) / 2);
}

double rotation_beyond_convention(const Mat3& C) {
  const auto canonical = canonical_correction(C, Vec3::Zero());
  if (!canonical) return NAN;
  return rotation_angle(C * canonical->matrix.inverse());
}

double dropped_share(const Mat3& C, const Mat3& kept) {
  const Eigen::JacobiSVD<Mat3> svd(C);
  return Eigen::JacobiSVD<Mat3>(Mat3(C - kept)).singularValues()(0) / svd.singularValues()(2);
}

}  // namespace scalcal
