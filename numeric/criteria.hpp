// The criteria as smooth functions of the positions, with exact gradients, written once for any
// scalar (double for Ipopt, Boost.Multiprecision for the polish). Every derivative comes from one
// identity: for phi(M) with d phi = tr(G dM), d phi / d eta_i = 2 J_i^T G h_i (J_i = dh/d eta).
#pragma once
#include <vector>

#include <Eigen/Cholesky>

#include "numeric/design.hpp"

namespace scalcal {

template <class Scalar> using Mat93T = Eigen::Matrix<Scalar, 9, 3>;
template <class Scalar> using PositionsT = std::vector<Vec3T<Scalar>>;

// J = dh/d eta for h = (x, y, z, x^2, y^2, z^2, xy, yz, zx).
template <class Scalar>
Mat93T<Scalar> design_jacobian(const Vec3T<Scalar>& e) {
  const Scalar zero(0), one(1), two(2);
  Mat93T<Scalar> J;
  J << one, zero, zero,
       zero, one, zero,
       zero, zero, one,
       two * e(0), zero, zero,
       zero, two * e(1), zero,
       zero, zero, two * e(2),
       e(1), e(0), zero,
       zero, e(2), e(1),
       e(2), zero, e(0);
  return J;
}

// Gradient of phi(M) with respect to every position, given G = d phi / dM (symmetric).
template <class Scalar>
PositionsT<Scalar> gradient_from_dM(const PositionsT<Scalar>& eta, const Mat9T<Scalar>& G) {
  PositionsT<Scalar> grad(eta.size());
  for (std::size_t i = 0; i < eta.size(); ++i) {
    const Vec9T<Scalar> Gh = G * design_row(eta[i]);
    grad[i] = Scalar(2) * (design_jacobian(eta[i]).transpose() * Gh);
  }
  return grad;
}

// K = M^-1 by Cholesky; `ok` is false when M is not numerically positive definite.
template <class Scalar>
Mat9T<Scalar> inverse_information(const Mat9T<Scalar>& M, bool& ok) {
  Eigen::LLT<Mat9T<Scalar>> llt(M);
  ok = llt.info() == Eigen::Success;
  return ok ? Mat9T<Scalar>(llt.solve(Mat9T<Scalar>::Identity())) : Mat9T<Scalar>::Zero();
}

// log D = log(N^9 det K) = -log det(M / N): the D objective, smooth and scale-free.
template <class Scalar>
Scalar log_d_criterion(const PositionsT<Scalar>& eta, PositionsT<Scalar>* grad, bool& ok) {
  using std::log;
  const Scalar N(static_cast<int>(eta.size()));
  const Mat9T<Scalar> M = information_matrix(eta);
  Eigen::LLT<Mat9T<Scalar>> llt(M / N);
  ok = llt.info() == Eigen::Success;
  if (!ok) return Scalar(0);
  Scalar logdet(0);
  for (int i = 0; i < 9; ++i) logdet += log(llt.matrixLLT()(i, i));
  if (grad) *grad = gradient_from_dM(eta, Mat9T<Scalar>(-llt.solve(Mat9T<Scalar>::Identity()) / N));
  return Scalar(-2) * logdet;
}

// A = N trace K; d A = -N tr(K dM K).
template <class Scalar>
Scalar a_criterion(const PositionsT<Scalar>& eta, PositionsT<Scalar>* grad, bool& ok) {
  const Scalar N(static_cast<int>(eta.size()));
  const Mat9T<Scalar> K = inverse_information(information_matrix(eta), ok);
  if (!ok) return Scalar(0);
  if (grad) *grad = gradient_from_dM(eta, Mat9T<Scalar>(-N * K * K));
  return N * K.trace();
}

// The nine N K(r,r), the functions whose maximum is S; gradients on request (one set per r).
template <class Scalar>
Vec9T<Scalar> diagonal_criteria(const PositionsT<Scalar>& eta, std::vector<PositionsT<Scalar>>* grads, bool& ok) {
  const Scalar N(static_cast<int>(eta.size()));
  const Mat9T<Scalar> K = inverse_information(information_matrix(eta), ok);
  if (!ok) return Vec9T<Scalar>::Zero();
  if (grads) {
    grads->resize(9);
    for (int r = 0; r < 9; ++r) {
      const Vec9T<Scalar> k = K.col(r);
      (*grads)[r] = gradient_from_dM(eta, Mat9T<Scalar>(-N * k * k.transpose()));
    }
  }
  return N * K.diagonal();
}

}  // namespace scalcal
