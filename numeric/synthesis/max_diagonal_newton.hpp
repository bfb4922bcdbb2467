// Newton on the first-order conditions of a max-diagonal criterion (min t s.t. N K(r,r) <= t) at the
// entries a program Ipopt has brought close makes active, in double: it carries S from Ipopt's
// tolerance (2e-12 above 6 + 3 sqrt 3 at N = 18) to rounding. The conditions are those of the MPFR
// polish (polish/polish_kkt.hpp); steps are minimum-norm, as rotations leave the Jacobian singular.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "numeric/criteria/derivatives.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/synthesis/criterion_ops.hpp"
#include "numeric/synthesis/local_result.hpp"
#include "numeric/synthesis/minimum_norm_solve.hpp"
#include "numeric/synthesis/synthesis_models.hpp"

namespace scalcal {

namespace max_diagonal_detail {

// Unknowns z = (x_1..x_N, t, mu_a for the active rows, nu_1..nu_N); residual F(z) of
//   sum_a mu_a grad g_a + 2 nu_i x_i = 0,  g_a = t,  sum_a mu_a = 1,  |x_i|^2 = 1,
// with g_a = N K(a,a) at the unnormalised positions x_i, and its Jacobian when J is non-null.
template <class Model>
bool kkt(const Eigen::VectorXd& z, int n, const std::vector<int>& active, Eigen::VectorXd& F, Eigen::MatrixXd* J) {
  const int m = static_cast<int>(active.size()), t0 = 3 * n, mu0 = t0 + 1, nu0 = mu0 + m, size = nu0 + n;
  PositionsT<double> eta(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) eta[static_cast<std::size_t>(i)] = z.segment<3>(3 * i);
  bool ok = true;
  std::vector<PositionsT<double>> grads;
  const std::vector<double> g = diagonal_pieces<Model>(eta, active, &grads, ok);
  if (!ok) return false;
  F.setZero(size);
  for (int a = 0; a < m; ++a) {
    const double mu = z(mu0 + a);
    for (int i = 0; i < n; ++i)
      F.segment<3>(3 * i) += mu * grads[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
  }
  for (int i = 0; i < n; ++i) F.segment<3>(3 * i) += 2 * z(nu0 + i) * z.segment<3>(3 * i);
  // Rows: 3N stationarity, then m equalities, one sum, N norms (the row count equals the unknowns).
  const int eq0 = t0, sum_row = t0 + m, norm0 = sum_row + 1;
  for (int a = 0; a < m; ++a) F(eq0 + a) = g[static_cast<std::size_t>(a)] - z(t0);
  F(sum_row) = z.segment(mu0, m).sum() - 1;
  for (int i = 0; i < n; ++i) F(norm0 + i) = z.segment<3>(3 * i).squaredNorm() - 1;
  if (!J) return true;
  J->setZero(size, size);
  const InformationT<Model, double> K = inverse_information(information_matrix<Model>(eta), ok);
  RowT<Model, double> l = RowT<Model, double>::Zero();
  for (int a = 0; a < m; ++a) l(active[static_cast<std::size_t>(a)]) = z(mu0 + a);
  const double N = n;
  const InformationT<Model, double> B = K * l.asDiagonal() * K;
  // sum_a mu_a N K(a,a): G = -N B, dG = N (K dM B + B dM K) (as MaxDiagonalProblem's Hessian).
  J->topLeftCorner(3 * n, 3 * n) = hessian_from_dM<Model>(eta, InformationT<Model, double>(-N * B), K, B, N);
  for (int i = 0; i < n; ++i) {
    J->block<3, 3>(3 * i, 3 * i) += 2 * z(nu0 + i) * Eigen::Matrix3d::Identity();
    J->block<3, 1>(3 * i, nu0 + i) = 2 * z.segment<3>(3 * i);
    J->block<1, 3>(norm0 + i, 3 * i) = 2 * z.segment<3>(3 * i).transpose();
  }
  for (int a = 0; a < m; ++a) {
    for (int i = 0; i < n; ++i) {
      const Vec3& gi = grads[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
      J->block<3, 1>(3 * i, mu0 + a) = gi;
      J->block<1, 3>(eq0 + a, 3 * i) = gi.transpose();
    }
    (*J)(eq0 + a, t0) = -1;
    (*J)(sum_row, mu0 + a) = 1;
  }
  return true;
}

}  // namespace max_diagonal_detail

// `best` refined by Newton on those conditions; unchanged unless the refined program has a lower
// value with every multiplier non-negative (else the active set read off `best` was not the
// optimum's). `criterion` is of the max-diagonal form (compiled once per model).
template <class Model>
LocalResult refine_active_diagonal(const CriterionOps<Model>& criterion, const LocalResult& best,
                                   int max_iterations = 8) {
  using namespace max_diagonal_detail;
  const int n = best.program.size();
  bool ok = true;
  const std::vector<int>& rows = criterion.rows;
  const std::vector<double> g = diagonal_pieces<Model>(best.program.positions, rows, nullptr, ok);
  if (!ok) return best;
  const double t = *std::max_element(g.begin(), g.end());
  std::vector<int> active;
  for (std::size_t a = 0; a < rows.size(); ++a)
    if (g[a] >= t * (1 - 1e-6)) active.push_back(rows[a]);
  const int m = static_cast<int>(active.size()), mu0 = 3 * n + 1, nu0 = mu0 + m;
  Eigen::VectorXd z = Eigen::VectorXd::Zero(nu0 + n);
  for (int i = 0; i < n; ++i) z.segment<3>(3 * i) = best.program.positions[static_cast<std::size_t>(i)];
  z(3 * n) = t;
  {
    // Multipliers: least squares of stationarity and sum mu = 1 at the given positions.
    std::vector<PositionsT<double>> grads;
    diagonal_pieces<Model>(best.program.positions, active, &grads, ok);
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3 * n + 1, m + n);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(3 * n + 1);
    for (int a = 0; a < m; ++a) {
      for (int i = 0; i < n; ++i)
        A.block<3, 1>(3 * i, a) = grads[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)];
      A(3 * n, a) = 1;
    }
    for (int i = 0; i < n; ++i) A.block<3, 1>(3 * i, m + i) = 2 * z.segment<3>(3 * i);
    b(3 * n) = 1;
    const Eigen::VectorXd w = minimum_norm_solve(A, b);
    z.segment(mu0, m) = w.head(m);
    z.segment(nu0, n) = w.tail(n);
  }
  Eigen::VectorXd F;
  Eigen::MatrixXd J;
  if (!kkt<Model>(z, n, active, F, &J)) return best;
  double residual = F.norm();
  for (int it = 0; it < max_iterations && residual > 1e-15 * std::max(1.0, t); ++it) {
    const Eigen::VectorXd trial = z - minimum_norm_solve(J, F, 1e-11);
    Eigen::VectorXd F_trial;
    if (!kkt<Model>(trial, n, active, F_trial, nullptr) || !(F_trial.norm() < residual)) break;
    z = trial;
    residual = F_trial.norm();
    kkt<Model>(z, n, active, F, &J);
  }
  if ((z.segment(mu0, m).array() < -1e-10).any()) return best;
  LocalResult out = best;
  Program refined;
  for (int i = 0; i < n; ++i) refined.positions.push_back(Vec3(z.segment<3>(3 * i)).normalized());
  const double value = criterion_value(criterion, refined);
  if (std::isfinite(value) && value < best.value) {
    out.program = std::move(refined);
    out.value = value;
  }
  return out;
}

template <MaxDiagonalCriterion C, class Model = Paper9Model>
LocalResult refine_max_diagonal(const LocalResult& best, int max_iterations = 8) {
  return refine_active_diagonal<Model>(criterion_ops<C, Model>(), best, max_iterations);
}

#define SCALCAL_REFINE_DIAGONAL_INSTANCES(prefix, M) \
  prefix template LocalResult refine_active_diagonal<M>(const CriterionOps<M>&, const LocalResult&, int);
#define SCALCAL_EXTERN_REFINE_DIAGONAL(M) SCALCAL_REFINE_DIAGONAL_INSTANCES(extern, M)
SCALCAL_FOR_EACH_SYNTHESIS_MODEL(SCALCAL_EXTERN_REFINE_DIAGONAL)
#undef SCALCAL_EXTERN_REFINE_DIAGONAL

}  // namespace scalcal
