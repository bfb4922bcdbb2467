// The linearised scalar model: the design row h(eta) of a measurement position (eq. 5) and the
// information matrix H^T H of a program, accumulated without forming H.
#pragma once
#include <vector>

#include "numeric/model/types.hpp"

namespace scalcal {

// h(eta) = (x, y, z, x^2, y^2, z^2, xy, yz, zx) for a unit vector eta = (x, y, z).
template <class Scalar>
Vec9T<Scalar> design_row(const Vec3T<Scalar>& eta) {
  Vec9T<Scalar> h;
  const Scalar& x = eta(0);
  const Scalar& y = eta(1);
  const Scalar& z = eta(2);
  h << x, y, z, x * x, y * y, z * z, x * y, y * z, z * x;
  return h;
}

template <class Scalar>
DesignMatrixT<Scalar> design_matrix(const std::vector<Vec3T<Scalar>>& positions) {
  DesignMatrixT<Scalar> H(static_cast<Eigen::Index>(positions.size()), 9);
  for (std::size_t i = 0; i < positions.size(); ++i)
    H.row(static_cast<Eigen::Index>(i)) = design_row(positions[i]).transpose();
  return H;
}

// H^T H = sum_i h_i h_i^T. Symmetric by construction (the lower triangle is mirrored).
template <class Scalar>
Mat9T<Scalar> information_matrix(const std::vector<Vec3T<Scalar>>& positions) {
  Mat9T<Scalar> M = Mat9T<Scalar>::Zero();
  for (const auto& eta : positions) {
    const Vec9T<Scalar> h = design_row(eta);
    M.template selfadjointView<Eigen::Lower>().rankUpdate(h);
  }
  M.template triangularView<Eigen::StrictlyUpper>() = M.transpose();
  return M;
}

}  // namespace scalcal
