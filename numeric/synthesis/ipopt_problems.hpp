// A criterion as a smooth nonlinear program over x = (eta_1..eta_N, extra variables), one class per
// form (criteria/criterion.hpp): SmoothForm min phi; MaxDiagonalForm min t s.t. N K(r,r) <= t (lifted
// at large N, max_diagonal_lifted.hpp); MaxEigenvalueForm max s s.t. M/N - s I = L L^T. Values, gradients and Hessians
// are exact (tests compare them with finite differences). The Ipopt adapter (ipopt_local.cpp) sees only SmoothProblem.
#pragma once
#include <algorithm>
#include <memory>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "numeric/criteria/derivatives.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/program/program.hpp"
#include "numeric/synthesis/criterion_ops.hpp"
#include "numeric/synthesis/max_diagonal_lifted.hpp"
#include "numeric/synthesis/smooth_problem.hpp"
#include "numeric/synthesis/symmetric_pairs.hpp"
#include "numeric/synthesis/synthesis_models.hpp"

namespace scalcal {

// A smooth criterion's objective over the positions, from its SmoothOps.
template <class Model>
class SmoothCriterionProblem : public SmoothProblem {
 public:
  static constexpr int P = Model::kParameters;
  SmoothCriterionProblem(int positions, SmoothOps<double, P> criterion)
      : SmoothProblem(positions), criterion_(criterion) {}
  bool long_runs() const override { return false; }
  bool objective(const double* x, double& f, double* grad) const override {
    const PositionsT<double> eta = positions_of(x);
    MatrixDerivatives<double, P> d;
    if (!criterion_.derivatives(information_matrix<Model>(eta), positions(), d)) return false;
    f = d.value;
    if (grad) scatter(gradient_from_dM<Model>(eta, d.G), grad);
    return true;
  }
  bool lagrangian_hessian(const double* x, double obj_factor, const double*, double* lower) const override {
    const PositionsT<double> eta = positions_of(x);
    MatrixDerivatives<double, P> d;
    if (!criterion_.derivatives(information_matrix<Model>(eta), positions(), d)) return false;
    pack_lower(hessian_from_dM<Model>(eta, d.G, d.A, d.B, d.c), obj_factor, variables(), lower);
    return true;
  }

 private:
  SmoothOps<double, P> criterion_;
};

// Epigraph of a max-diagonal criterion: min t s.t. N K(r,r) - t <= 0 for r in its rows.
template <class Model>
class MaxDiagonalProblem : public SmoothProblem {
 public:
  static constexpr int P = Model::kParameters;
  MaxDiagonalProblem(int positions, std::vector<int> rows) : SmoothProblem(positions), rows_(std::move(rows)) {}
  int extra() const override { return 1; }
  int constraints() const override { return static_cast<int>(rows_.size()); }
  std::vector<double> start(const Program& program) const override {
    std::vector<double> x = SmoothProblem::start(program);
    bool ok;
    const std::vector<double> d = diagonal_pieces<Model>(program.positions, rows_, nullptr, ok);
    x.back() = ok ? 1.01 * *std::max_element(d.begin(), d.end()) : 1e6;
    return x;
  }
  // sum_r lambda_r N K(r,r): G = -N K diag(lambda) K, dG = N (K dM B + B dM K), B = K diag(lambda) K
  // (hessian_from_dM is linear in (G, B) for fixed A and c); t enters linearly.
  bool lagrangian_hessian(const double* x, double, const double* lambda, double* lower) const override {
    const PositionsT<double> eta = positions_of(x);
    bool ok;
    const InformationT<Model, double> K = inverse_information(information_matrix<Model>(eta), ok);
    if (!ok) return false;
    const double N = positions();
    RowT<Model, double> l = RowT<Model, double>::Zero();
    for (std::size_t a = 0; a < rows_.size(); ++a) l(rows_[a]) = lambda[a];
    const InformationT<Model, double> B = K * l.asDiagonal() * K;
    pack_lower(hessian_from_dM<Model>(eta, InformationT<Model, double>(-N * B), K, B, N), 1.0, variables(), lower);
    return true;
  }
  void constraint_bounds(double* lower, double* upper) const override {
    std::fill(lower, lower + constraints(), -2e19);
    std::fill(upper, upper + constraints(), 0.0);
  }
  bool objective(const double* x, double& f, double* grad) const override {
    f = x[3 * positions()];
    if (grad) grad[3 * positions()] = 1.0;
    return true;
  }
  bool constraint_values(const double* x, double* g, double* jac) const override {
    bool ok;
    std::vector<PositionsT<double>> grads;
    const std::vector<double> d = diagonal_pieces<Model>(positions_of(x), rows_, jac ? &grads : nullptr, ok);
    if (!ok) return false;
    const int n = variables(), t = 3 * positions();
    for (int r = 0; r < constraints(); ++r) {
      g[r] = d[static_cast<std::size_t>(r)] - x[t];
      if (!jac) continue;
      scatter(grads[static_cast<std::size_t>(r)], jac + r * n);
      jac[r * n + t] = -1.0;
    }
    return true;
  }

 private:
  std::vector<int> rows_;
};

// E without smoothing: lambda_min(M/N) >= s exactly when M/N - s I = L L^T for some lower
// triangular L, so max s over (eta, s, L) gives E = 1/s at the optimum, multiple eigenvalues or not.
template <class Model>
class MaxEigenvalueProblem : public SmoothProblem {
 public:
  static constexpr int P = Model::kParameters;
  static constexpr int kPairs = P * (P + 1) / 2;  // (a, b), b <= a, at index a(a+1)/2 + b
  using MatP = InformationT<Model, double>;
  using RowP = RowT<Model, double>;
  using SmoothProblem::SmoothProblem;
  static int pair(int a, int b) { return symmetric_pair(a, b); }
  static int column_of_pair(int k) {
    int a = 0;
    while ((a + 1) * (a + 2) / 2 <= k) ++a;
    return k - a * (a + 1) / 2;
  }
  int extra() const override { return 1 + kPairs; }
  int constraints() const override { return kPairs; }
  std::vector<double> start(const Program& program) const override {
    std::vector<double> x = SmoothProblem::start(program);
    const MatP A = information_matrix<Model>(program.positions) / static_cast<double>(program.size());
    const double s = 0.5 * Eigen::SelfAdjointEigenSolver<MatP>(A, Eigen::EigenvaluesOnly).eigenvalues()(0);
    const MatP L = Eigen::LLT<MatP>(A - s * MatP::Identity()).matrixL();
    const std::size_t base = static_cast<std::size_t>(3 * positions());
    x[base] = s;
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) x[base + 1 + static_cast<std::size_t>(pair(a, b))] = L(a, b);
    return x;
  }
  void constraint_bounds(double* lower, double* upper) const override {
    std::fill(lower, lower + kPairs, 0.0);
    std::fill(upper, upper + kPairs, 0.0);
  }
  bool objective(const double* x, double& f, double* grad) const override {
    f = -x[3 * positions()];
    if (grad) grad[3 * positions()] = -1.0;
    return true;
  }
  // sum_ab lambda_ab g_ab = tr(Lambda M)/N - s tr(Lambda) - tr(Lambda L L^T), Lambda symmetric with
  // the off-diagonal multipliers halved: position block i is (2/N)(J_i^T Lambda J_i + T(Lambda h_i)),
  // and d^2 / dL(a,m) dL(b,m) = -2 Lambda(a,b).
  bool lagrangian_hessian(const double* x, double, const double* lambda, double* lower) const override {
    const int N = positions(), n = variables(), l0 = 3 * N + 1;
    std::fill(lower, lower + n * (n + 1) / 2, 0.0);
    auto at = [lower](int r, int c) -> double& {
      return r >= c ? lower[r * (r + 1) / 2 + c] : lower[c * (c + 1) / 2 + r];
    };
    MatP Lambda;
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) Lambda(a, b) = Lambda(b, a) = a == b ? lambda[pair(a, b)] : 0.5 * lambda[pair(a, b)];
    for (int i = 0; i < N; ++i) {
      const Vec3 e(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
      const JacobianT<Model, double> J = Model::jacobian(e);
      const RowP w = Lambda * Model::row(e);
      const Mat3 block = (2.0 / N) * (J.transpose() * Lambda * J + Model::curvature(w, e));
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c <= r; ++c) at(3 * i + r, 3 * i + c) = block(r, c);
    }
    for (int m = 0; m < P; ++m)
      for (int a = m; a < P; ++a)
        for (int b = m; b <= a; ++b) at(l0 + pair(a, m), l0 + pair(b, m)) = -2.0 * Lambda(a, b);
    return true;
  }
  // Position blocks are 3 x 3 on the diagonal, s is linear, and L(a, m) meets only L(b, m).
  bool hessian_entry_used(int r, int c) const override {
    const int s = 3 * positions(), l0 = s + 1;
    if (r < s && c < s) return r / 3 == c / 3;
    if (r < l0 || c < l0) return false;
    return column_of_pair(r - l0) == column_of_pair(c - l0);
  }
  bool constraint_values(const double* x, double* g, double* jac) const override {
    const int N = positions(), n = variables(), s = 3 * N, l0 = 3 * N + 1;
    const PositionsT<double> eta = positions_of(x);
    const MatP A = information_matrix<Model>(eta) / static_cast<double>(N);
    MatP L = MatP::Zero();
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) L(a, b) = x[l0 + pair(a, b)];
    const MatP LLt = L * L.transpose();
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) g[pair(a, b)] = A(a, b) - (a == b ? x[s] : 0.0) - LLt(a, b);
    if (!jac) return true;
    std::vector<RowP> h(static_cast<std::size_t>(N));
    std::vector<JacobianT<Model, double>> J(static_cast<std::size_t>(N));
    for (int i = 0; i < N; ++i) {
      h[static_cast<std::size_t>(i)] = Model::row(eta[static_cast<std::size_t>(i)]);
      J[static_cast<std::size_t>(i)] = Model::jacobian(eta[static_cast<std::size_t>(i)]);
    }
    for (int a = 0; a < P; ++a)
      for (int b = 0; b <= a; ++b) {
        double* row = jac + pair(a, b) * n;
        for (int i = 0; i < N; ++i) {
          const auto& hi = h[static_cast<std::size_t>(i)];
          const auto& Ji = J[static_cast<std::size_t>(i)];
          const Vec3 d = (Ji.row(a).transpose() * hi(b) + hi(a) * Ji.row(b).transpose()) / static_cast<double>(N);
          for (int c = 0; c < 3; ++c) row[3 * i + c] += d(c);
        }
        if (a == b) row[s] -= 1.0;
        for (int m = 0; m <= b; ++m) {
          row[l0 + pair(a, m)] -= L(b, m);
          row[l0 + pair(b, m)] -= L(a, m);
        }
      }
    return true;
  }
};

// Where a max-diagonal criterion's program switches from the epigraph over the positions (a dense
// Hessian, cheap below this N, and the form the documented sweeps of N = 9..40 ran) to the lifted form
// (max_diagonal_lifted.hpp: sparse, O(N) per iteration).
inline constexpr int kLiftedFromPositions = 48;

// The nonlinear program of a criterion under the model, chosen by the criterion's form.
template <class Model>
std::unique_ptr<SmoothProblem> make_problem(const CriterionOps<Model>& criterion, int positions) {
  switch (criterion.form) {
    case CriterionForm::Smooth:
      return std::make_unique<SmoothCriterionProblem<Model>>(positions, criterion.smooth);
    case CriterionForm::MaxDiagonal:
      if (positions >= kLiftedFromPositions)
        return std::make_unique<MaxDiagonalLiftedProblem<Model>>(positions, criterion.rows);
      return std::make_unique<MaxDiagonalProblem<Model>>(positions, criterion.rows);
    default:
      return std::make_unique<MaxEigenvalueProblem<Model>>(positions);
  }
}

template <Criterion C, class Model = Paper9Model>
std::unique_ptr<SmoothProblem> make_problem(int positions) {
  return make_problem<Model>(criterion_ops<C, Model>(), positions);
}

// The same for a registered criterion chosen at run time, under the paper's model.
inline std::unique_ptr<SmoothProblem> make_problem(CriterionKind criterion, int positions) {
  return visit_criterion(criterion, [positions](auto C) { return make_problem<decltype(C)>(positions); });
}

#define SCALCAL_IPOPT_PROBLEM_INSTANCES(prefix, M) \
  prefix template std::unique_ptr<SmoothProblem> make_problem<M>(const CriterionOps<M>&, int);
#define SCALCAL_EXTERN_IPOPT_PROBLEM(M) SCALCAL_IPOPT_PROBLEM_INSTANCES(extern, M)
SCALCAL_FOR_EACH_SYNTHESIS_MODEL(SCALCAL_EXTERN_IPOPT_PROBLEM)
#undef SCALCAL_EXTERN_IPOPT_PROBLEM

}  // namespace scalcal
