// Newton on the KKT conditions at W = 2P + 30 digits. Unknowns z = (eta, [t, mu], nu):
//   smooth f (D: log D, A):  grad f + 2 nu_i eta_i = 0,            |eta_i|^2 = 1;
//   S (min t, g_r <= t):     sum mu_r grad g_r + 2 nu_i eta_i = 0,  sum mu_r = 1,  g_r = t (r active),
//                            |eta_i|^2 = 1.
// The Jacobian of these conditions is formed by central differences with step 10^-(P+15), which
// at W digits is accurate far beyond P digits; steps are minimum-norm least-squares solutions.
#include "numeric/polish/polish.hpp"

#include <cmath>
#include <functional>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/QR>

#include "numeric/criteria/derivatives.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/polish/polish_eigenvalue.hpp"

namespace scalcal {

namespace polish_detail {

Real newton_least_squares(const std::function<VecX(const VecX&)>& residual, VecX& z, int P, int max_iterations,
                          int& iterations, bool regularised) {
  const Real h = pow(Real(10), -(P + 15));
  const Real target = converged_residual(P);
  VecX F = residual(z);
  Real norm = F.norm();
  for (int it = 0; it < max_iterations && norm > target; ++it) {
    MatX J(F.size(), z.size());
    for (int j = 0; j < z.size(); ++j) {
      VecX zp = z, zm = z;
      zp(j) += h;
      zm(j) -= h;
      J.col(j) = (residual(zp) - residual(zm)) / (Real(2) * h);
    }
    VecX step;
    if (regularised) {
      MatX A = MatX::Zero(J.cols(), J.cols());
      A.selfadjointView<Eigen::Lower>().rankUpdate(J.transpose());
      A.diagonal().array() += norm * norm;
      step = A.selfadjointView<Eigen::Lower>().llt().solve(-(J.transpose() * F));
    } else {
      Eigen::CompleteOrthogonalDecomposition<MatX> cod(J);
      cod.setThreshold(Real(1e-25));
      step = cod.solve(-F);
    }
    // Damping only as a safeguard: from a double optimum the full step is taken every time.
    Real lambda(1);
    VecX trial = z + step;
    VecX Ft = residual(trial);
    for (int k = 0; k < 8 && !(Ft.norm() < norm); ++k) {
      lambda /= 2;
      trial = z + lambda * step;
      Ft = residual(trial);
    }
    ++iterations;
    if (!(Ft.norm() < norm)) break;
    const bool stalled = regularised && !(Ft.norm() < norm / 2);
    z = trial;
    F = Ft;
    norm = F.norm();
    if (stalled) break;
  }
  return norm;
}

Real converged_residual(int P) { return pow(Real(10), -(P + 10)); }

int digits_left_by(const Real& residual, int P) {
  const double lost = residual > 0 ? -static_cast<double>(log10(residual)) - 2 : P;
  return std::max(1, std::min(P, static_cast<int>(std::floor(lost))));
}

}  // namespace polish_detail

namespace {

using namespace polish_detail;

PositionsT<Real> positions_of(const VecX& z, int n) {
  PositionsT<Real> eta(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) eta[static_cast<std::size_t>(i)] = Vec3T<Real>(z(3 * i), z(3 * i + 1), z(3 * i + 2));
  return eta;
}

// The first-order conditions of one criterion, as a residual of the unknowns z.
struct Conditions {
  int n = 0;          // positions
  CriterionKind criterion = CriterionKind::D;
  std::vector<int> active;  // S: the active diagonal elements

  int unknowns() const { return criterion == CriterionKind::S ? 4 * n + 1 + static_cast<int>(active.size()) : 4 * n; }
  int equations() const { return unknowns(); }

  VecX residual(const VecX& z) const {
    const PositionsT<Real> eta = positions_of(z, n);
    VecX F = VecX::Zero(equations());
    bool ok = true;
    std::vector<Vec3T<Real>> g;
    int nu0 = 3 * n;
    if (criterion == CriterionKind::S) {
      const int m = static_cast<int>(active.size());
      std::vector<PositionsT<Real>> grads;
      const Vec9T<Real> d = diagonal_criteria(eta, &grads, ok);
      g.assign(static_cast<std::size_t>(n), Vec3T<Real>::Zero());
      const Real t = z(3 * n);
      Real sum_mu(0);
      for (int a = 0; a < m; ++a) {
        const Real mu = z(3 * n + 1 + a);
        sum_mu += mu;
        for (int i = 0; i < n; ++i) g[static_cast<std::size_t>(i)] += mu * grads[static_cast<std::size_t>(active[static_cast<std::size_t>(a)])][static_cast<std::size_t>(i)];
        F(3 * n + 1 + a) = d(active[static_cast<std::size_t>(a)]) - t;
      }
      F(3 * n) = Real(1) - sum_mu;
      nu0 = 3 * n + 1 + m;
    } else if (criterion == CriterionKind::D) {
      log_d_criterion(eta, &g, ok);
    } else {
      a_criterion(eta, &g, ok);
    }
    for (int i = 0; i < n; ++i) {
      const Real nu = z(nu0 + i);
      const auto& e = eta[static_cast<std::size_t>(i)];
      for (int c = 0; c < 3; ++c) F(3 * i + c) = g[static_cast<std::size_t>(i)](c) + Real(2) * nu * e(c);
      F(nu0 + i) = e.squaredNorm() - Real(1);
    }
    return F;
  }

  // Multipliers that best satisfy stationarity at the given positions (a linear least-squares fit).
  void initial_multipliers(VecX& z) const {
    const int m = criterion == CriterionKind::S ? static_cast<int>(active.size()) : 0;
    const int nu0 = criterion == CriterionKind::S ? 3 * n + 1 + m : 3 * n;
    const int rows = 3 * n + (m > 0 ? 1 : 0), cols = m + n;
    const PositionsT<Real> eta = positions_of(z, n);
    MatX A = MatX::Zero(rows, cols);
    VecX b = VecX::Zero(rows);
    bool ok = true;
    if (criterion == CriterionKind::S) {
      std::vector<PositionsT<Real>> grads;
      const Vec9T<Real> d = diagonal_criteria(eta, &grads, ok);
      Real t = d(active[0]);
      for (int r : active) t = std::max(t, d(r));
      z(3 * n) = t;
      for (int a = 0; a < m; ++a) {
        for (int i = 0; i < n; ++i)
          for (int c = 0; c < 3; ++c) A(3 * i + c, a) = grads[static_cast<std::size_t>(active[static_cast<std::size_t>(a)])][static_cast<std::size_t>(i)](c);
        A(3 * n, a) = Real(1);
      }
      b(3 * n) = Real(1);
    } else {
      std::vector<Vec3T<Real>> g;
      if (criterion == CriterionKind::D) log_d_criterion(eta, &g, ok);
      else a_criterion(eta, &g, ok);
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) b(3 * i + c) = -g[static_cast<std::size_t>(i)](c);
    }
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) A(3 * i + c, m + i) = Real(2) * eta[static_cast<std::size_t>(i)](c);
    const VecX x = A.completeOrthogonalDecomposition().solve(b);
    for (int a = 0; a < m; ++a) z(3 * n + 1 + a) = x(a);
    for (int i = 0; i < n; ++i) z(nu0 + i) = x(m + i);
  }
};

}  // namespace

PolishResult polish(const Program& program, CriterionKind criterion, const PolishOptions& options) {
  PolishResult out;
  out.program = program;
  const int P = std::max(options.digits, 1);
  out.supported = true;
  const unsigned W = static_cast<unsigned>(2 * P + 30);
  PrecisionGuard guard(W);
  if (criterion == CriterionKind::E) return polish_eigenvalue(program, options);
  const int n = program.size();
  Conditions kkt;
  kkt.n = n;
  kkt.criterion = criterion;
  if (criterion == CriterionKind::S) {
    bool ok = true;
    const Vec9 d = diagonal_criteria<double>(program.positions, nullptr, ok);
    for (int r = 0; r < 9; ++r)
      if (d(r) >= d.maxCoeff() * (1 - 1e-6)) kkt.active.push_back(r);
    out.active = static_cast<int>(kkt.active.size());
  }
  VecX z = VecX::Zero(kkt.unknowns());
  for (int i = 0; i < n; ++i) {
    const Vec3 e = program.positions[static_cast<std::size_t>(i)].normalized();
    for (int c = 0; c < 3; ++c) z(3 * i + c) = Real(e(c));
  }
  kkt.initial_multipliers(z);

  const Real norm = newton_least_squares([&](const VecX& x) { return kkt.residual(x); }, z, P, options.max_iterations,
                                         out.iterations);
  out.residual = static_cast<double>(norm);
  out.converged = norm <= converged_residual(P);

  ProgramTpl<Real> polished;
  for (int i = 0; i < n; ++i) {
    const Vec3T<Real> e(z(3 * i), z(3 * i + 1), z(3 * i + 2));
    polished.positions.push_back(e / e.norm());
  }
  const EvaluationTpl<Real> ev = evaluate(polished);
  const Real value = criterion == CriterionKind::D ? ev.D : criterion == CriterionKind::A ? ev.A : ev.S;
  // A residual r moves the value by O(r) at most: claim only the digits it leaves untouched.
  out.digits = out.converged ? P : digits_left_by(norm, P);
  out.value_digits = value.str(out.digits, std::ios_base::showpoint);
  out.program = polished.cast<double>();
  return out;
}

}  // namespace scalcal
