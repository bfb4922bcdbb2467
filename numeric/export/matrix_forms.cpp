// The forms a target stores a correction in (matrix_forms.hpp).
#include "numeric/export/matrix_forms.hpp"

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

double rotation_angle(const Mat3& R) { return std::acos(std::clamp((R.trace() - 1) / 2, -1.0, 1.0)); }

double dropped_share(const Mat3& C, const Mat3& kept) {
  const Eigen::JacobiSVD<Mat3> svd(C);
  return Eigen::JacobiSVD<Mat3>(Mat3(C - kept)).singularValues()(0) / svd.singularValues()(2);
}

}  // namespace scalcal
