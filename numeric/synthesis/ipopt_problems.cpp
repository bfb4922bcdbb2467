#include "numeric/synthesis/ipopt_problems.hpp"

#include <algorithm>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "numeric/criteria/derivatives.hpp"

namespace scalcal {

std::vector<double> SmoothProblem::start(const Program& program) const {
  std::vector<double> x(static_cast<std::size_t>(variables()), 0.0);
  for (int i = 0; i < positions_; ++i)
    for (int c = 0; c < 3; ++c) x[static_cast<std::size_t>(3 * i + c)] = program.positions[static_cast<std::size_t>(i)](c);
  return x;
}

std::vector<Vec3> SmoothProblem::positions_of(const double* x) const {
  std::vector<Vec3> eta(static_cast<std::size_t>(positions_));
  for (int i = 0; i < positions_; ++i) eta[static_cast<std::size_t>(i)] = Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
  return eta;
}

namespace {

void scatter(const std::vector<Vec3>& grad, double* out) {
  for (std::size_t i = 0; i < grad.size(); ++i)
    for (int c = 0; c < 3; ++c) out[3 * i + static_cast<std::size_t>(c)] += grad[i](c);
}

// Writes factor * H (the 3N x 3N position block) into the packed lower triangle of all variables.
template <class Matrix>
void pack_lower(const Matrix& H, double factor, int variables, double* lower) {
  std::fill(lower, lower + variables * (variables + 1) / 2, 0.0);
  for (int r = 0, k = 0; r < H.rows(); ++r)
    for (int c = 0; c <= r; ++c, ++k) lower[k] = factor * H(r, c);
}

class DProblem : public SmoothProblem {
 public:
  using SmoothProblem::SmoothProblem;
  bool objective(const double* x, double& f, double* grad) const override {
    bool ok;
    std::vector<Vec3> g;
    f = log_d_criterion(positions_of(x), grad ? &g : nullptr, ok);
    if (ok && grad) scatter(g, grad);
    return ok;
  }
  bool has_hessian() const override { return true; }
  bool lagrangian_hessian(const double* x, double obj_factor, const double*, double* lower) const override {
    bool ok;
    const auto H = log_d_hessian(positions_of(x), ok);
    if (ok) pack_lower(H, obj_factor, variables(), lower);
    return ok;
  }
};

class AProblem : public SmoothProblem {
 public:
  using SmoothProblem::SmoothProblem;
  bool objective(const double* x, double& f, double* grad) const override {
    bool ok;
    std::vector<Vec3> g;
    f = a_criterion(positions_of(x), grad ? &g : nullptr, ok);
    if (ok && grad) scatter(g, grad);
    return ok;
  }
  bool has_hessian() const override { return true; }
  bool lagrangian_hessian(const double* x, double obj_factor, const double*, double* lower) const override {
    bool ok;
    const auto H = a_hessian(positions_of(x), ok);
    if (ok) pack_lower(H, obj_factor, variables(), lower);
    return ok;
  }
};

// Epigraph of the max-diagonal criterion: min t s.t. N K(r,r) - t <= 0, r = 0..8.
class SProblem : public SmoothProblem {
 public:
  using SmoothProblem::SmoothProblem;
  int extra() const override { return 1; }
  int constraints() const override { return 9; }
  std::vector<double> start(const Program& program) const override {
    std::vector<double> x = SmoothProblem::start(program);
    bool ok;
    const Vec9 d = diagonal_criteria<double>(program.positions, nullptr, ok);
    x.back() = ok ? 1.01 * d.maxCoeff() : 1e6;
    return x;
  }
  // sum_r lambda_r N K(r,r): G = -N K diag(lambda) K, dG = N (K dM B + B dM K), B = K diag(lambda) K
  // (hessian_from_dM is linear in (G, B) for fixed A and c); t enters linearly.
  bool has_hessian() const override { return true; }
  bool lagrangian_hessian(const double* x, double, const double* lambda, double* lower) const override {
    const std::vector<Vec3> eta = positions_of(x);
    bool ok;
    const Mat9 K = inverse_information(information_matrix(eta), ok);
    if (!ok) return false;
    const double N = positions();
    Vec9 l;
    for (int r = 0; r < 9; ++r) l(r) = lambda[r];
    const Mat9 B = K * l.asDiagonal() * K;
    pack_lower(hessian_from_dM<double>(eta, Mat9(-N * B), K, B, N), 1.0, variables(), lower);
    return true;
  }
  void constraint_bounds(double* lower, double* upper) const override {
    std::fill(lower, lower + 9, -2e19);
    std::fill(upper, upper + 9, 0.0);
  }
  bool objective(const double* x, double& f, double* grad) const override {
    f = x[3 * positions()];
    if (grad) grad[3 * positions()] = 1.0;
    return true;
  }
  bool constraint_values(const double* x, double* g, double* jac) const override {
    bool ok;
    std::vector<std::vector<Vec3>> grads;
    const Vec9 d = diagonal_criteria(positions_of(x), jac ? &grads : nullptr, ok);
    if (!ok) return false;
    const int n = variables(), t = 3 * positions();
    for (int r = 0; r < 9; ++r) {
      g[r] = d(r) - x[t];
      if (!jac) continue;
      scatter(grads[static_cast<std::size_t>(r)], jac + r * n);
      jac[r * n + t] = -1.0;
    }
    return true;
  }
};

// E without smoothing: lambda_min(M/N) >= s exactly when M/N - s I = L L^T for some lower
// triangular L, so max s over (eta, s, L) gives E = 1/s at the optimum, multiple eigenvalues or not.
class EProblem : public SmoothProblem {
 public:
  using SmoothProblem::SmoothProblem;
  static constexpr int kPairs = 45;  // (a, b), b <= a, at index a(a+1)/2 + b
  static int pair(int a, int b) { return a >= b ? a * (a + 1) / 2 + b : b * (b + 1) / 2 + a; }
  int extra() const override { return 1 + kPairs; }
  int constraints() const override { return kPairs; }
  std::vector<double> start(const Program& program) const override {
    std::vector<double> x = SmoothProblem::start(program);
    const Mat9 A = information_matrix(program.positions) / static_cast<double>(program.size());
    const double s = 0.5 * Eigen::SelfAdjointEigenSolver<Mat9>(A, Eigen::EigenvaluesOnly).eigenvalues()(0);
    const Mat9 L = Eigen::LLT<Mat9>(A - s * Mat9::Identity()).matrixL();
    const std::size_t base = static_cast<std::size_t>(3 * positions());
    x[base] = s;
    for (int a = 0; a < 9; ++a)
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
  bool has_hessian() const override { return true; }
  bool lagrangian_hessian(const double* x, double, const double* lambda, double* lower) const override {
    const int N = positions(), n = variables(), l0 = 3 * N + 1;
    std::fill(lower, lower + n * (n + 1) / 2, 0.0);
    auto at = [lower](int r, int c) -> double& { return r >= c ? lower[r * (r + 1) / 2 + c] : lower[c * (c + 1) / 2 + r]; };
    Mat9 Lambda;
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b <= a; ++b) Lambda(a, b) = Lambda(b, a) = a == b ? lambda[pair(a, b)] : 0.5 * lambda[pair(a, b)];
    for (int i = 0; i < N; ++i) {
      const Vec3 e(x[3 * i], x[3 * i + 1], x[3 * i + 2]);
      const Mat93 J = design_jacobian(e);
      const Vec9 w = Lambda * design_row(e);
      Eigen::Matrix3d T;
      T << 2 * w(3), w(6), w(8), w(6), 2 * w(4), w(7), w(8), w(7), 2 * w(5);
      const Eigen::Matrix3d block = (2.0 / N) * (J.transpose() * Lambda * J + T);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c <= r; ++c) at(3 * i + r, 3 * i + c) = block(r, c);
    }
    for (int m = 0; m < 9; ++m)
      for (int a = m; a < 9; ++a)
        for (int b = m; b <= a; ++b) at(l0 + pair(a, m), l0 + pair(b, m)) = -2.0 * Lambda(a, b);
    return true;
  }
  bool constraint_values(const double* x, double* g, double* jac) const override {
    const int N = positions(), n = variables(), s = 3 * N, l0 = 3 * N + 1;
    const std::vector<Vec3> eta = positions_of(x);
    const Mat9 A = information_matrix(eta) / static_cast<double>(N);
    Mat9 L = Mat9::Zero();
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b <= a; ++b) L(a, b) = x[l0 + pair(a, b)];
    const Mat9 LLt = L * L.transpose();
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b <= a; ++b) g[pair(a, b)] = A(a, b) - (a == b ? x[s] : 0.0) - LLt(a, b);
    if (!jac) return true;
    std::vector<Vec9> h(static_cast<std::size_t>(N));
    std::vector<Mat93> J(static_cast<std::size_t>(N));
    for (int i = 0; i < N; ++i) {
      h[static_cast<std::size_t>(i)] = design_row(eta[static_cast<std::size_t>(i)]);
      J[static_cast<std::size_t>(i)] = design_jacobian(eta[static_cast<std::size_t>(i)]);
    }
    for (int a = 0; a < 9; ++a)
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

 private:
  using Mat93 = Mat93T<double>;
};

}  // namespace

std::unique_ptr<SmoothProblem> make_problem(CriterionKind criterion, int positions) {
  switch (criterion) {
    case CriterionKind::D: return std::make_unique<DProblem>(positions);
    case CriterionKind::A: return std::make_unique<AProblem>(positions);
    case CriterionKind::E: return std::make_unique<EProblem>(positions);
    case CriterionKind::S: return std::make_unique<SProblem>(positions);
  }
  throw std::invalid_argument("make_problem: unknown criterion");
}

}  // namespace scalcal
