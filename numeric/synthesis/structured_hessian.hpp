// The Riemannian Hessian of a function of M = sum_i h(eta_i) h(eta_i)^T over N unit vectors, kept in
// its structure: a 2 x 2 block per position plus a coupling of rank at most Q = P(P+1)/2,
//   H = D + U^T W U,  U t = the entries m_ab (a >= b) of dM(t), the first-order change of M along t,
//   t^T U^T W U t = 2c tr(dM A dM B)   (d phi = tr(G dM), dG = c (A dM B + B dM A): criteria/criterion.hpp),
//   D_i = 2 B_i^T T(G h_i) B_i + 2 T_i^T G T_i - (eta_i . grad_i) I   (T_i = J_i B_i, B_i the tangent basis),
// which is SphereNewton's dense 2N x 2N Hessian term by term. Kept so, a product H t, a solve with
// H + mu I (Woodbury) and the inertia of H + mu I (Sylvester's law through the Schur complements of
// [[D, V^T], [V, -Sigma]], W = V^T Sigma V, Sigma = +-1: In(H) = In(D) + In(Sigma + V D^-1 V^T) - In(Sigma))
// cost O(N Q^2) instead of the O(N^3) of a dense factorisation: at N = 1000 a few milliseconds.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>

#include "numeric/criteria/criterion.hpp"
#include "numeric/model/design.hpp"
#include "numeric/synthesis/sphere_newton.hpp"
#include "numeric/synthesis/symmetric_pairs.hpp"

namespace scalcal {

template <class Model>
class StructuredHessian {
 public:
  static constexpr int P = Model::kParameters;
  static constexpr int Q = P * (P + 1) / 2;
  using VecX = Eigen::VectorXd;
  using MatX = Eigen::MatrixXd;
  using MatP = InformationT<Model, double>;
  using Basis = Eigen::Matrix<double, 3, 2>;
  struct Inertia {
    int negative = 0, zero = 0, positive = 0;
  };

  // The model at eta for the derivatives d of the criterion there.
  void assemble(const std::vector<Vec3>& eta, const MatrixDerivatives<double, P>& d);

  int size() const { return 2 * n_; }
  const VecX& gradient() const { return g_; }  // Riemannian, in the tangent bases
  const Basis& basis(int i) const { return bases_[static_cast<std::size_t>(i)]; }
  VecX apply(const VecX& t) const;  // H t
  MatX dense() const;               // H itself (tests)
  double mean_diagonal() const;     // trace H / 2N: the Hessian's scale

  // Prepares solve() and inertia() for H + mu I. False when a block of D + mu I or the Schur
  // complement is singular to rounding: another mu will do.
  bool factor(double mu);
  const Inertia& inertia() const { return inertia_; }
  VecX solve(const VecX& b) const;  // (H + mu I)^-1 b

 private:
  static int pair(int a, int b) { return symmetric_pair(a, b); }
  void coupling(const MatP& A, const MatP& B, double c);  // W_, then V_ and sigma_

  int n_ = 0;
  std::vector<Basis> bases_;
  std::vector<Eigen::Matrix2d> D_;
  Eigen::Matrix<double, Q, Eigen::Dynamic> U_;
  Eigen::Matrix<double, Q, Q> W_;
  MatX V_;      // r x 2N: |lambda_k|^1/2 e_k^T U over the r nonzero eigenpairs of W
  VecX sigma_;  // their signs
  VecX g_;
  // factor(mu):
  std::vector<Eigen::Matrix2d> Dinv_;
  MatX S_vectors_;
  VecX S_values_;
  Inertia inertia_;
};

template <class Model>
void StructuredHessian<Model>::assemble(const std::vector<Vec3>& eta, const MatrixDerivatives<double, P>& d) {
  n_ = static_cast<int>(eta.size());
  bases_.resize(eta.size());
  D_.resize(eta.size());
  U_.resize(Q, 2 * n_);
  g_.resize(2 * n_);
  for (int i = 0; i < n_; ++i) {
    const Vec3& e = eta[static_cast<std::size_t>(i)];
    const RowT<Model, double> h = Model::row(e);
    const JacobianT<Model, double> J = Model::jacobian(e);
    const Basis& Bi = bases_[static_cast<std::size_t>(i)] = tangent_basis(e);
    const Eigen::Matrix<double, P, 2> T = J * Bi;
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) U_.template block<1, 2>(pair(a, b), 2 * i) = T.row(a) * h(b) + h(a) * T.row(b);
    const RowT<Model, double> w = d.G * h;
    const Vec3 egrad = 2.0 * (J.transpose() * w);
    g_.template segment<2>(2 * i) = Bi.transpose() * egrad;
    D_[static_cast<std::size_t>(i)] = 2.0 * (Bi.transpose() * Model::curvature(w, e) * Bi) +
                                      2.0 * (T.transpose() * d.G * T) - e.dot(egrad) * Eigen::Matrix2d::Identity();
  }
  coupling(d.A, d.B, d.c);
}

template <class Model>
void StructuredHessian<Model>::coupling(const MatP& A, const MatP& B, double c) {
  // W(q1, q2) = c [tr(S1 A S2 B) + tr(S1 B S2 A)] (symmetric_pairs.hpp).
  W_ = c * pair_trace_form<P>(A, B);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, Q, Q>> es(W_);
  const double largest = es.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<int> kept;
  for (int k = 0; k < Q; ++k)
    if (std::abs(es.eigenvalues()(k)) > 1e-14 * largest) kept.push_back(k);
  const int r = static_cast<int>(kept.size());
  V_.resize(r, 2 * n_);
  sigma_.resize(r);
  for (int j = 0; j < r; ++j) {
    const double lambda = es.eigenvalues()(kept[static_cast<std::size_t>(j)]);
    sigma_(j) = lambda > 0 ? 1.0 : -1.0;
    V_.row(j).noalias() =
        std::sqrt(std::abs(lambda)) * (es.eigenvectors().col(kept[static_cast<std::size_t>(j)]).transpose() * U_);
  }
}

template <class Model>
typename StructuredHessian<Model>::VecX StructuredHessian<Model>::apply(const VecX& t) const {
  VecX out = U_.transpose() * (W_ * (U_ * t));
  for (int i = 0; i < n_; ++i)
    out.template segment<2>(2 * i) += D_[static_cast<std::size_t>(i)] * t.template segment<2>(2 * i);
  return out;
}

template <class Model>
typename StructuredHessian<Model>::MatX StructuredHessian<Model>::dense() const {
  MatX H = U_.transpose() * W_ * U_;
  for (int i = 0; i < n_; ++i) H.template block<2, 2>(2 * i, 2 * i) += D_[static_cast<std::size_t>(i)];
  return H;
}

template <class Model>
double StructuredHessian<Model>::mean_diagonal() const {
  double trace = (W_ * (U_ * U_.transpose())).trace();
  for (const auto& Di : D_) trace += Di.trace();
  return trace / std::max(1, size());
}

template <class Model>
bool StructuredHessian<Model>::factor(double mu) {
  // The blocks of D + mu I, their inertia, and S = Sigma + V (D + mu I)^-1 V^T.
  Dinv_.resize(D_.size());
  inertia_ = {};
  double scale = std::abs(mu);
  for (const auto& Di : D_) scale = std::max(scale, Di.cwiseAbs().maxCoeff());
  const double tiny = 1e-13 * std::max(scale, std::numeric_limits<double>::min());
  int block_negative = 0;
  for (std::size_t i = 0; i < D_.size(); ++i) {
    const Eigen::Matrix2d Dm = D_[i] + mu * Eigen::Matrix2d::Identity();
    const double tr = Dm.trace(), det = Dm.determinant();
    const double disc = std::sqrt(std::max(0.0, 0.25 * tr * tr - det));
    const double l1 = 0.5 * tr - disc, l2 = 0.5 * tr + disc;  // eigenvalues of the symmetric 2 x 2 block
    if (std::abs(l1) <= tiny || std::abs(l2) <= tiny) return false;
    block_negative += (l1 < 0) + (l2 < 0);
    Dinv_[i] << Dm(1, 1), -Dm(0, 1), -Dm(1, 0), Dm(0, 0);
    Dinv_[i] /= det;
  }
  const int r = static_cast<int>(V_.rows());
  MatX Y(r, 2 * n_);
  for (int i = 0; i < n_; ++i)
    Y.template middleCols<2>(2 * i).noalias() = V_.template middleCols<2>(2 * i) * Dinv_[static_cast<std::size_t>(i)];
  MatX S = sigma_.asDiagonal();
  S.noalias() += Y * V_.transpose();
  S = (0.5 * (S + S.transpose())).eval();
  const Eigen::SelfAdjointEigenSolver<MatX> es(S);
  S_vectors_ = es.eigenvectors();
  S_values_ = es.eigenvalues();
  const double s_tiny = 1e-12 * std::max(1.0, S_values_.cwiseAbs().maxCoeff());
  int s_positive = 0, sigma_positive = 0;
  for (int k = 0; k < r; ++k) {
    if (std::abs(S_values_(k)) <= s_tiny) return false;
    s_positive += S_values_(k) > 0;
    sigma_positive += sigma_(k) > 0;
  }
  inertia_.negative = block_negative + s_positive - sigma_positive;
  inertia_.positive = size() - inertia_.negative;
  return true;
}

template <class Model>
typename StructuredHessian<Model>::VecX StructuredHessian<Model>::solve(const VecX& b) const {
  // Woodbury: (D + V^T Sigma V)^-1 = D^-1 - D^-1 V^T S^-1 V D^-1.
  VecX x(b.size());
  for (int i = 0; i < n_; ++i)
    x.template segment<2>(2 * i) = Dinv_[static_cast<std::size_t>(i)] * b.template segment<2>(2 * i);
  const VecX y = S_vectors_ * ((S_vectors_.transpose() * (V_ * x)).cwiseQuotient(S_values_));
  const VecX z = V_.transpose() * y;
  for (int i = 0; i < n_; ++i)
    x.template segment<2>(2 * i) -= Dinv_[static_cast<std::size_t>(i)] * z.template segment<2>(2 * i);
  return x;
}

}  // namespace scalcal
