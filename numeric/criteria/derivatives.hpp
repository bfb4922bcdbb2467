// Derivatives of a criterion of M = H^T H with respect to the positions, written once for any
// model and scalar (double for Ipopt and Newton, MPFR for the polish). Every derivative comes from
// one identity: for phi(M) with d phi = tr(G dM), d phi / d eta_i = 2 J_i^T G h_i (J_i = dh/d eta).
#pragma once
#include <type_traits>
#include <vector>

#include <Eigen/Cholesky>

#include "numeric/criteria/criterion.hpp"
#include "numeric/model/design.hpp"

namespace scalcal {

template <class Scalar>
using MatXT = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

// Gradient of phi(M) with respect to every position, given G = d phi / dM (symmetric).
template <class Model = Paper9Model, class Scalar>
PositionsT<Scalar> gradient_from_dM(const PositionsT<Scalar>& eta, const InformationT<Model, Scalar>& G) {
  PositionsT<Scalar> grad(eta.size());
  for (std::size_t i = 0; i < eta.size(); ++i) {
    const RowT<Model, Scalar> Gh = G * Model::row(eta[i]);
    grad[i] = Scalar(2) * (Model::jacobian(eta[i]).transpose() * Gh);
  }
  return grad;
}

// Hessian (3N x 3N, dense) of phi(M) with respect to the positions, when d phi = tr(G dM) and
// dG = c (A dM B + B dM A) (D: G = -K, A = B = K, c = 1/2; A: G = -N K^2, A = K, B = K^2, c = N).
// With d grad_i = 2 (T(G h_i) + J_i^T G J_i) d eta_i + 2 J_i^T dG h_i and
// dM = sum_j (J_j d eta_j h_j^T + h_j d eta_j^T J_j^T), block (i, j) is
//   2c [ (h_j^T B h_i) J_i^T A J_j + (J_i^T A h_j)(J_j^T B h_i)^T + (A <-> B) ]
// plus, for i = j, 2 T(G h_i) + 2 J_i^T G J_i, where T(w) = Model::curvature(w, eta_i).
template <class Model = Paper9Model, class Scalar>
MatXT<Scalar> hessian_from_dM(const PositionsT<Scalar>& eta, const InformationT<Model, Scalar>& G,
                              const InformationT<Model, Scalar>& A, const InformationT<Model, Scalar>& B,
                              const Scalar& c) {
  const int n = static_cast<int>(eta.size());
  std::vector<RowT<Model, Scalar>> h(eta.size()), Ah(eta.size()), Bh(eta.size());
  std::vector<JacobianT<Model, Scalar>> J(eta.size()), AJ(eta.size()), BJ(eta.size());
  for (std::size_t i = 0; i < eta.size(); ++i) {
    h[i] = Model::row(eta[i]);
    J[i] = Model::jacobian(eta[i]);
    Ah[i] = A * h[i];
    Bh[i] = B * h[i];
    AJ[i] = A * J[i];
    BJ[i] = B * J[i];
  }
  MatXT<Scalar> H(3 * n, 3 * n);
  const Scalar two_c = Scalar(2) * c, two(2);
  for (std::size_t i = 0; i < eta.size(); ++i)
    for (std::size_t j = 0; j <= i; ++j) {
      const Scalar bij = h[j].dot(Bh[i]), aij = h[j].dot(Ah[i]);
      Mat3T<Scalar> block = bij * (J[i].transpose() * AJ[j]) + aij * (J[i].transpose() * BJ[j]) +
                            (J[i].transpose() * Ah[j]) * (J[j].transpose() * Bh[i]).transpose() +
                            (J[i].transpose() * Bh[j]) * (J[j].transpose() * Ah[i]).transpose();
      block *= two_c;
      if (i == j) {
        const RowT<Model, Scalar> w = G * h[i];
        block += two * Model::curvature(w, eta[i]) + two * (J[i].transpose() * G * J[i]);
      }
      H.template block<3, 3>(3 * static_cast<int>(i), 3 * static_cast<int>(j)) = block;
      H.template block<3, 3>(3 * static_cast<int>(j), 3 * static_cast<int>(i)) = block.transpose();
    }
  return H;
}

// K = M^-1 by Cholesky; `ok` is false when M is not numerically positive definite.
template <class Scalar, int P>
Eigen::Matrix<Scalar, P, P> inverse_information(const Eigen::Matrix<Scalar, P, P>& M, bool& ok) {
  Eigen::LLT<Eigen::Matrix<Scalar, P, P>> llt(M);
  ok = llt.info() == Eigen::Success;
  return ok ? Eigen::Matrix<Scalar, P, P>(llt.solve(Eigen::Matrix<Scalar, P, P>::Identity()))
            : Eigen::Matrix<Scalar, P, P>::Zero();
}

// A smooth criterion's objective over the positions, with its gradient on request.
template <SmoothCriterion C, class Model = Paper9Model, class Scalar>
Scalar smooth_objective(const PositionsT<Scalar>& eta, std::type_identity_t<PositionsT<Scalar>>* grad, bool& ok) {
  MatrixDerivatives<Scalar, Model::kParameters> d;
  ok = C::derivatives(information_matrix<Model>(eta), static_cast<int>(eta.size()), d);
  if (!ok) return Scalar(0);
  if (grad) *grad = gradient_from_dM<Model>(eta, d.G);
  return d.value;
}

// Its Hessian over the positions (3N x 3N).
template <SmoothCriterion C, class Model = Paper9Model, class Scalar>
MatXT<Scalar> smooth_hessian(const PositionsT<Scalar>& eta, bool& ok) {
  MatrixDerivatives<Scalar, Model::kParameters> d;
  ok = C::derivatives(information_matrix<Model>(eta), static_cast<int>(eta.size()), d);
  if (!ok) return {};
  return hessian_from_dM<Model>(eta, d.G, d.A, d.B, d.c);
}

// The pieces N K(r,r), r in `rows`, of a max-diagonal criterion, with their gradients on request.
template <class Model = Paper9Model, class Scalar>
std::vector<Scalar> diagonal_pieces(const PositionsT<Scalar>& eta, const std::vector<int>& rows,
                                    std::type_identity_t<std::vector<PositionsT<Scalar>>>* grads, bool& ok) {
  const Scalar N(static_cast<int>(eta.size()));
  const InformationT<Model, Scalar> K = inverse_information(information_matrix<Model>(eta), ok);
  if (!ok) return {};
  std::vector<Scalar> out;
  if (grads) grads->clear();
  for (int r : rows) {
    out.push_back(N * K(r, r));
    if (grads) {
      const RowT<Model, Scalar> k = K.col(r);
      grads->push_back(gradient_from_dM<Model>(eta, InformationT<Model, Scalar>(-N * k * k.transpose())));
    }
  }
  return out;
}

}  // namespace scalcal
