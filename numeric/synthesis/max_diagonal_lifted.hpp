// A max-diagonal criterion (S) for Ipopt at large N, lifted so that its KKT system is sparse: the
// entries of Y = M/N become variables held by Q = P(P+1)/2 equality rows, and the criterion reads Y
// alone,
//   min t  s.t.  y_ab - (1/N) sum_i h_a(eta_i) h_b(eta_i) = 0,   (Y^-1)(r,r) - t <= 0  (N K(r,r) = (Y^-1)(r,r)).
// The Lagrangian Hessian is then one 3 x 3 block per position (the equality rows' curvature) and a
// dense Q x Q block on Y (the rows r), as for E's LL^T form (ipopt_problems.hpp): the linear solver
// eliminates the positions and factorises a Q x Q Schur complement, O(N Q^2) where the epigraph over
// the positions alone has a dense 3N x 3N Hessian (S at N = 500: 56 s for 8 starts, 9 s per dense KKT
// factorisation chain). The same optimum: the two programs have the same feasible positions and values.
#pragma once
#include <algorithm>
#include <vector>

#include <Eigen/Cholesky>

#include "numeric/synthesis/smooth_problem.hpp"
#include "numeric/synthesis/symmetric_pairs.hpp"

namespace scalcal {

template <class Model>
class MaxDiagonalLiftedProblem : public SmoothProblem {
 public:
  static constexpr int P = Model::kParameters;
  static constexpr int Q = P * (P + 1) / 2;  // (a, b), b <= a, at index a(a+1)/2 + b
  using MatP = InformationT<Model, double>;

  MaxDiagonalLiftedProblem(int positions, std::vector<int> rows) : SmoothProblem(positions), rows_(std::move(rows)) {}
  int extra() const override { return 1 + Q; }
  int constraints() const override { return Q + static_cast<int>(rows_.size()); }
  static int pair(int a, int b) { return symmetric_pair(a, b); }

  std::vector<double> start(const Program& program) const override {
    std::vector<double> x = SmoothProblem::start(program);
    const MatP Y = information_matrix<Model>(program.positions) / static_cast<double>(program.size());
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) x[static_cast<std::size_t>(y0() + pair(a, b))] = Y(a, b);
    Eigen::LLT<MatP> llt(Y);
    double top = 1e6;
    if (llt.info() == Eigen::Success) {
      const MatP Z = llt.solve(MatP::Identity());
      top = 0;
      for (int r : rows_) top = std::max(top, Z(r, r));
      top *= 1.01;
    }
    x[static_cast<std::size_t>(t0())] = top;
    return x;
  }
  void constraint_bounds(double* lower, double* upper) const override {
    std::fill(lower, lower + Q, 0.0);
    std::fill(upper, upper + Q, 0.0);
    std::fill(lower + Q, lower + constraints(), -2e19);
    std::fill(upper + Q, upper + constraints(), 0.0);
  }
  bool objective(const double* x, double& f, double* grad) const override {
    f = x[t0()];
    if (grad) grad[t0()] = 1.0;
    return true;
  }
  bool constraint_values(const double* x, double* g, double* jac) const override;
  bool lagrangian_hessian(const double* x, double obj_factor, const double* lambda, double* lower) const override;
  bool lagrangian_hessian_entries(const double* x, double obj_factor, const double* lambda,
                                  double* values) const override;
  // The positions' 3 x 3 blocks and the Y block; t enters linearly.
  bool hessian_entry_used(int r, int c) const override {
    const int s = 3 * positions();
    if (r < s && c < s) return r / 3 == c / 3;
    return r >= y0() && c >= y0();
  }

 private:
  int t0() const { return 3 * positions(); }
  int y0() const { return 3 * positions() + 1; }
  // Z = Y^-1 from the y variables (false: Y not positive definite).
  bool inverse(const double* x, MatP& Z) const;
  // The Lagrangian's blocks: per position -(2/N)(J^T Lambda J + T(Lambda h)), and on Y
  // sum_r mu_r d^2 (Y^-1)(r,r) = tr(S1 Z S2 B) + tr(S1 B S2 Z) for B = Z diag(mu) Z (S_ab = E_ab + E_ba).
  bool blocks(const double* x, const double* lambda, std::vector<Mat3>& position, Eigen::Matrix<double, Q, Q>& y) const;

  std::vector<int> rows_;
};

template <class Model>
bool MaxDiagonalLiftedProblem<Model>::inverse(const double* x, MatP& Z) const {
  MatP Y;
  for (int a = 0; a < P; ++a)
    for (int b = 0; b <= a; ++b) Y(a, b) = Y(b, a) = x[y0() + pair(a, b)];
  Eigen::LLT<MatP> llt(Y);
  if (llt.info() != Eigen::Success) return false;
  Z = llt.solve(MatP::Identity());
  return true;
}

template <class Model>
bool MaxDiagonalLiftedProblem<Model>::constraint_values(const double* x, double* g, double* jac) const {
  const int N = positions(), n = variables();
  const PositionsT<double> eta = positions_of(x);
  const MatP A = information_matrix<Model>(eta) / static_cast<double>(N);
  for (int a = 0; a < P; ++a)
    for (int b = 0; b <= a; ++b) g[pair(a, b)] = x[y0() + pair(a, b)] - A(a, b);
  MatP Z;
  if (!inverse(x, Z)) return false;
  const int m = static_cast<int>(rows_.size());
  for (int k = 0; k < m; ++k)
    g[Q + k] = Z(rows_[static_cast<std::size_t>(k)], rows_[static_cast<std::size_t>(k)]) - x[t0()];
  if (!jac) return true;
  for (int i = 0; i < N; ++i) {
    const Vec3& e = eta[static_cast<std::size_t>(i)];
    const RowT<Model, double> h = Model::row(e);
    const JacobianT<Model, double> J = Model::jacobian(e);
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) {
        const Vec3 d = -(J.row(a).transpose() * h(b) + h(a) * J.row(b).transpose()) / static_cast<double>(N);
        double* row = jac + pair(a, b) * n;
        for (int c = 0; c < 3; ++c) row[3 * i + c] = d(c);
      }
  }
  for (int q = 0; q < Q; ++q) jac[q * n + y0() + q] = 1.0;
  // d (Y^-1)(r,r) / d y_ab = -(Z(r,a) Z(b,r) + Z(r,b) Z(a,r)), halved on the diagonal a = b.
  for (int k = 0; k < m; ++k) {
    const int r = rows_[static_cast<std::size_t>(k)];
    double* row = jac + (Q + k) * n;
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) row[y0() + pair(a, b)] = a == b ? -Z(r, a) * Z(r, a) : -2 * Z(r, a) * Z(r, b);
    row[t0()] = -1.0;
  }
  return true;
}

template <class Model>
bool MaxDiagonalLiftedProblem<Model>::blocks(const double* x, const double* lambda, std::vector<Mat3>& position,
                                             Eigen::Matrix<double, Q, Q>& y) const {
  const int N = positions();
  MatP Lambda;  // off-diagonal multipliers halved: sum_ab lambda_ab h_a h_b = h^T Lambda h
  for (int a = 0; a < P; ++a)
    for (int b = 0; b <= a; ++b) Lambda(a, b) = Lambda(b, a) = a == b ? lambda[pair(a, b)] : 0.5 * lambda[pair(a, b)];
  position.resize(static_cast<std::size_t>(N));
  for (int i = 0; i < N; ++i) {
    const Vec3 e(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
    const JacobianT<Model, double> J = Model::jacobian(e);
    const RowT<Model, double> w = Lambda * Model::row(e);
    position[static_cast<std::size_t>(i)] = (-2.0 / N) * (J.transpose() * Lambda * J + Model::curvature(w, e));
  }
  MatP Z;
  if (!inverse(x, Z)) return false;
  RowT<Model, double> mu = RowT<Model, double>::Zero();
  for (std::size_t k = 0; k < rows_.size(); ++k) mu(rows_[k]) += lambda[Q + static_cast<int>(k)];
  const MatP B = Z * mu.asDiagonal() * Z;
  y = pair_trace_form<P>(Z, B);  // tr(S1 Z S2 B) + tr(S1 B S2 Z) (symmetric_pairs.hpp)
  return true;
}

template <class Model>
bool MaxDiagonalLiftedProblem<Model>::lagrangian_hessian(const double* x, double, const double* lambda,
                                                         double* lower) const {
  std::vector<Mat3> position;
  Eigen::Matrix<double, Q, Q> y;
  if (!blocks(x, lambda, position, y)) return false;
  const int n = variables();
  std::fill(lower, lower + static_cast<std::size_t>(n) * static_cast<std::size_t>(n + 1) / 2, 0.0);
  auto at = [lower](int r, int c) -> double& {
    return lower[static_cast<std::size_t>(r) * static_cast<std::size_t>(r + 1) / 2 + static_cast<std::size_t>(c)];
  };
  for (int i = 0; i < positions(); ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c <= r; ++c) at(3 * i + r, 3 * i + c) = position[static_cast<std::size_t>(i)](r, c);
  for (int q1 = 0; q1 < Q; ++q1)
    for (int q2 = 0; q2 <= q1; ++q2) at(y0() + q1, y0() + q2) = y(q1, q2);
  return true;
}

template <class Model>
bool MaxDiagonalLiftedProblem<Model>::lagrangian_hessian_entries(const double* x, double, const double* lambda,
                                                                 double* values) const {
  std::vector<Mat3> position;
  Eigen::Matrix<double, Q, Q> y;
  if (!blocks(x, lambda, position, y)) return false;
  std::size_t k = 0;  // the adapter's order: row by row, c <= r
  for (int i = 0; i < positions(); ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c <= r; ++c) values[k++] = position[static_cast<std::size_t>(i)](r, c);
  for (int q1 = 0; q1 < Q; ++q1)
    for (int q2 = 0; q2 <= q1; ++q2) values[k++] = y(q1, q2);
  return true;
}

}  // namespace scalcal
