// The criteria as smooth functions of the positions, with exact gradients, written once for any
// scalar (double for Ipopt, Boost.Multiprecision for the polish). Every derivative comes from one
// identity: for phi(M) with d phi = tr(G dM), d phi / d eta_i = 2 J_i^T G h_i (J_i = dh/d eta).
#pragma once
#include <vector>

#include <Eigen/Cholesky>

#include "numeric/model/design.hpp"

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

// Hessian (3N x 3N, dense) of phi(M) with respect to the positions, when d phi = tr(G dM) and
// dG = c (A dM B + B dM A) (D: G = -K, A = B = K, c = 1/2; A: G = -N K^2, A = K, B = K^2, c = N).
// With d grad_i = 2 (T(G h_i) + J_i^T G J_i) d eta_i + 2 J_i^T dG h_i and
// dM = sum_j (J_j d eta_j h_j^T + h_j d eta_j^T J_j^T), block (i, j) is
//   2c [ (h_j^T B h_i) J_i^T A J_j + (J_i^T A h_j)(J_j^T B h_i)^T + (A <-> B) ]
// plus, for i = j, 2 T(G h_i) + 2 J_i^T G J_i, where T(w) = sum_a w_a d^2 h_a / d eta^2.
template <class Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> hessian_from_dM(const PositionsT<Scalar>& eta,
                                                                      const Mat9T<Scalar>& G, const Mat9T<Scalar>& A,
                                                                      const Mat9T<Scalar>& B, const Scalar& c) {
  const int n = static_cast<int>(eta.size());
  using Mat3 = Eigen::Matrix<Scalar, 3, 3>;
  std::vector<Vec9T<Scalar>> h(eta.size()), Ah(eta.size()), Bh(eta.size());
  std::vector<Mat93T<Scalar>> J(eta.size()), AJ(eta.size()), BJ(eta.size());
  for (std::size_t i = 0; i < eta.size(); ++i) {
    h[i] = design_row(eta[i]);
    J[i] = design_jacobian(eta[i]);
    Ah[i] = A * h[i];
    Bh[i] = B * h[i];
    AJ[i] = A * J[i];
    BJ[i] = B * J[i];
  }
  Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> H(3 * n, 3 * n);
  const Scalar two_c = Scalar(2) * c, two(2);
  for (std::size_t i = 0; i < eta.size(); ++i)
    for (std::size_t j = 0; j <= i; ++j) {
      const Scalar bij = h[j].dot(Bh[i]), aij = h[j].dot(Ah[i]);
      Mat3 block = bij * (J[i].transpose() * AJ[j]) + aij * (J[i].transpose() * BJ[j]) +
                   (J[i].transpose() * Ah[j]) * (J[j].transpose() * Bh[i]).transpose() +
                   (J[i].transpose() * Bh[j]) * (J[j].transpose() * Ah[i]).transpose();
      block *= two_c;
      if (i == j) {
        const Vec9T<Scalar> w = G * h[i];
        Mat3 T;
        T << two * w(3), w(6), w(8),
             w(6), two * w(4), w(7),
             w(8), w(7), two * w(5);
        block += two * T + two * (J[i].transpose() * G * J[i]);
      }
      H.template block<3, 3>(3 * static_cast<int>(i), 3 * static_cast<int>(j)) = block;
      H.template block<3, 3>(3 * static_cast<int>(j), 3 * static_cast<int>(i)) = block.transpose();
    }
  return H;
}

// K = M^-1 by Cholesky; `ok` is false when M is not numerically positive definite.
template <class Scalar>
Mat9T<Scalar> inverse_information(const Mat9T<Scalar>& M, bool& ok) {
  Eigen::LLT<Mat9T<Scalar>> llt(M);
  ok = llt.info() == Eigen::Success;
  return ok ? Mat9T<Scalar>(llt.solve(Mat9T<Scalar>::Identity())) : Mat9T<Scalar>::Zero();
}

// Hessians of the D and A objectives below (same scaling), dense 3N x 3N; ok as for the values.
template <class Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> log_d_hessian(const PositionsT<Scalar>& eta, bool& ok) {
  const Mat9T<Scalar> K = inverse_information(information_matrix(eta), ok);
  if (!ok) return {};
  return hessian_from_dM<Scalar>(eta, Mat9T<Scalar>(-K), K, K, Scalar(1) / Scalar(2));
}

template <class Scalar>
Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> a_hessian(const PositionsT<Scalar>& eta, bool& ok) {
  const Scalar N(static_cast<int>(eta.size()));
  const Mat9T<Scalar> K = inverse_information(information_matrix(eta), ok);
  if (!ok) return {};
  const Mat9T<Scalar> K2 = K * K;
  return hessian_from_dM<Scalar>(eta, Mat9T<Scalar>(-N * K2), K, K2, N);
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
