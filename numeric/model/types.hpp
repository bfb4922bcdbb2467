// Fixed-size Eigen types of the linearised scalar model, templated on the scalar so the same
// code runs in double and in Boost.Multiprecision. Nine parameters: bias (3), scale-factor
// deviation (3), non-orthogonality (3), in the order of the paper's vector X (eq. 5).
#pragma once
#include <Eigen/Core>

namespace scalcal {

inline constexpr int kParameters = 9;

template <class Scalar> using Vec3T = Eigen::Matrix<Scalar, 3, 1>;
template <class Scalar> using Vec9T = Eigen::Matrix<Scalar, 9, 1>;
template <class Scalar> using Mat3T = Eigen::Matrix<Scalar, 3, 3>;
template <class Scalar> using Mat9T = Eigen::Matrix<Scalar, 9, 9>;
template <class Scalar> using DesignMatrixT = Eigen::Matrix<Scalar, Eigen::Dynamic, 9>;

using Vec3 = Vec3T<double>;
using Vec9 = Vec9T<double>;
using Mat3 = Mat3T<double>;
using Mat9 = Mat9T<double>;
using DesignMatrix = DesignMatrixT<double>;

}  // namespace scalcal
