// The model-independent part of the structured Riemannian Hessian (structured_hessian.hpp): the
// coupling's eigen-decomposition, H t, the factorisation of H + mu I with its inertia, and the solve.
#include "numeric/synthesis/structured_hessian.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Eigenvalues>

namespace scalcal {

void StructuredHessianCore::resize(int n, int q) {
  n_ = n;
  bases_.resize(static_cast<std::size_t>(n));
  D_.resize(static_cast<std::size_t>(n));
  U_.resize(q, 2 * n);
  g_.resize(2 * n);
}

void StructuredHessianCore::coupling(MatX W) {
  W_ = std::move(W);
  const int q = static_cast<int>(W_.rows());
  const Eigen::SelfAdjointEigenSolver<MatX> es(W_);
  const double largest = es.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<int> kept;
  for (int k = 0; k < q; ++k)
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

StructuredHessianCore::VecX StructuredHessianCore::apply(const VecX& t) const {
  VecX out = U_.transpose() * (W_ * (U_ * t));
  for (int i = 0; i < n_; ++i) out.segment<2>(2 * i) += D_[static_cast<std::size_t>(i)] * t.segment<2>(2 * i);
  return out;
}

StructuredHessianCore::MatX StructuredHessianCore::dense() const {
  MatX H = U_.transpose() * W_ * U_;
  for (int i = 0; i < n_; ++i) H.block<2, 2>(2 * i, 2 * i) += D_[static_cast<std::size_t>(i)];
  return H;
}

double StructuredHessianCore::mean_diagonal() const {
  double trace = (W_ * (U_ * U_.transpose())).trace();
  for (const auto& Di : D_) trace += Di.trace();
  return trace / std::max(1, size());
}

bool StructuredHessianCore::factor(double mu) {
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
    Y.middleCols<2>(2 * i).noalias() = V_.middleCols<2>(2 * i) * Dinv_[static_cast<std::size_t>(i)];
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

StructuredHessianCore::VecX StructuredHessianCore::solve(const VecX& b) const {
  // Woodbury: (D + V^T Sigma V)^-1 = D^-1 - D^-1 V^T S^-1 V D^-1.
  VecX x(b.size());
  for (int i = 0; i < n_; ++i) x.segment<2>(2 * i) = Dinv_[static_cast<std::size_t>(i)] * b.segment<2>(2 * i);
  const VecX y = S_vectors_ * ((S_vectors_.transpose() * (V_ * x)).cwiseQuotient(S_values_));
  const VecX z = V_.transpose() * y;
  for (int i = 0; i < n_; ++i) x.segment<2>(2 * i) -= Dinv_[static_cast<std::size_t>(i)] * z.segment<2>(2 * i);
  return x;
}

}  // namespace scalcal
