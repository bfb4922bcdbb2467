// The polish of the smooth and max-diagonal forms: Newton on the KKT conditions at W = 2P + 30
// digits. Unknowns z = (eta, [t, mu], nu):
//   smooth f:               grad f + 2 nu_i eta_i = 0,            |eta_i|^2 = 1;
//   max-diagonal (min t, g_r <= t): sum mu_r grad g_r + 2 nu_i eta_i = 0, sum mu_r = 1, g_r = t (r active),
//                           |eta_i|^2 = 1.
#pragma once
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/QR>

#include "numeric/criteria/derivatives.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/polish/newton_least_squares.hpp"
#include "numeric/polish/polish.hpp"
#include "numeric/polish/polish_ops.hpp"
#include "numeric/polish/value_text.hpp"

namespace scalcal::polish_detail {

inline PositionsT<Real> positions_of(const VecX& z, int n) {
  PositionsT<Real> eta(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) eta[static_cast<std::size_t>(i)] = Vec3T<Real>(z(3 * i), z(3 * i + 1), z(3 * i + 2));
  return eta;
}

// The first-order conditions of a criterion, as a residual of the unknowns z. `active` holds the
// active pieces of a max-diagonal criterion (indices into its rows), empty for a smooth one.
template <class Model>
struct KktConditions {
  const PolishOps<Model>& criterion;
  bool pieces = false;  // the max-diagonal form
  int n = 0;
  std::vector<int> active;  // rows r of K(r,r) that reach the maximum

  int multipliers() const { return pieces ? 1 + static_cast<int>(active.size()) : 0; }
  int unknowns() const { return 4 * n + multipliers(); }

  // Stationarity's gradient term at eta, with the multipliers mu of z (max-diagonal form).
  PositionsT<Real> gradient(const PositionsT<Real>& eta, const VecX& z, VecX& F) const {
    bool ok = true;
    PositionsT<Real> g;
    if (pieces) {
      std::vector<PositionsT<Real>> grads;
      const std::vector<Real> d = diagonal_pieces<Model>(eta, active, &grads, ok);
      g.assign(static_cast<std::size_t>(n), Vec3T<Real>::Zero());
      const Real t = z(3 * n);
      Real sum_mu(0);
      for (std::size_t a = 0; a < active.size(); ++a) {
        const Real mu = z(3 * n + 1 + static_cast<int>(a));
        sum_mu += mu;
        for (int i = 0; i < n; ++i) g[static_cast<std::size_t>(i)] += mu * grads[a][static_cast<std::size_t>(i)];
        F(3 * n + 1 + static_cast<int>(a)) = d[a] - t;
      }
      F(3 * n) = Real(1) - sum_mu;
    } else {
      smooth_gradient(eta, g, ok);
    }
    if (!ok) g.clear();  // M is not positive definite at eta: no gradient
    return g;
  }

  // An infinite residual where the information matrix is singular, so Newton backs off from there.
  VecX residual(const VecX& z) const {
    const PositionsT<Real> eta = positions_of(z, n);
    VecX F = VecX::Zero(unknowns());
    const PositionsT<Real> g = gradient(eta, z, F);
    if (g.size() != static_cast<std::size_t>(n)) return VecX::Constant(unknowns(), Real(INFINITY));
    const int nu0 = 3 * n + multipliers();
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
    const int m = pieces ? static_cast<int>(active.size()) : 0;
    const int nu0 = 3 * n + multipliers();
    const int rows = 3 * n + (pieces ? 1 : 0), cols = m + n;
    const PositionsT<Real> eta = positions_of(z, n);
    MatX A = MatX::Zero(rows, cols);
    VecX b = VecX::Zero(rows);
    bool ok = true;
    if (pieces) {
      std::vector<PositionsT<Real>> grads;
      const std::vector<Real> d = diagonal_pieces<Model>(eta, active, &grads, ok);
      if (!ok) throw std::invalid_argument("polish: the information matrix is singular at the start");
      z(3 * n) = *std::max_element(d.begin(), d.end());
      for (int a = 0; a < m; ++a) {
        for (int i = 0; i < n; ++i)
          for (int c = 0; c < 3; ++c)
            A(3 * i + c, a) = grads[static_cast<std::size_t>(a)][static_cast<std::size_t>(i)](c);
        A(3 * n, a) = Real(1);
      }
      b(3 * n) = Real(1);
    } else {
      PositionsT<Real> g;
      smooth_gradient(eta, g, ok);
      if (!ok) throw std::invalid_argument("polish: the information matrix is singular at the start");
      for (int i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) b(3 * i + c) = -g[static_cast<std::size_t>(i)](c);
    }
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) A(3 * i + c, m + i) = Real(2) * eta[static_cast<std::size_t>(i)](c);
    const VecX x = A.completeOrthogonalDecomposition().solve(b);
    for (int a = 0; a < m; ++a) z(3 * n + 1 + a) = x(a);
    for (int i = 0; i < n; ++i) z(nu0 + i) = x(m + i);
  }

  // The smooth criterion's gradient over the positions.
  void smooth_gradient(const PositionsT<Real>& eta, PositionsT<Real>& g, bool& ok) const {
    MatrixDerivatives<Real, Model::kParameters> d;
    ok = criterion.derivatives(information_matrix<Model>(eta), static_cast<int>(eta.size()), d);
    if (ok) g = gradient_from_dM<Model>(eta, d.G);
  }
};

// Runs under the caller's precision guard (W = 2P + 30 digits). Compiled once for the paper's model
// (polish_kkt.cpp), for the smooth and the max-diagonal form.
template <class Model>
PolishResult polish_kkt(const PolishOps<Model>& criterion, const Program& program, const PolishOptions& options) {
  PolishResult out;
  out.program = program;
  const int P = std::max(options.digits, 1);
  const int n = program.size();
  KktConditions<Model> kkt{criterion, criterion.form == PolishForm::MaxDiagonal, n, {}};
  if (kkt.pieces) {
    bool ok = true;
    const std::vector<int>& rows = criterion.rows;
    const std::vector<double> d = diagonal_pieces<Model>(program.positions, rows, nullptr, ok);
    if (!ok) throw std::invalid_argument("polish: the information matrix of the program is singular");
    const double top = *std::max_element(d.begin(), d.end());
    for (std::size_t a = 0; a < rows.size(); ++a)
      if (d[a] >= top * (1 - 1e-6)) kkt.active.push_back(rows[a]);
    out.active = static_cast<int>(kkt.active.size());
  }
  VecX z = VecX::Zero(kkt.unknowns());
  for (int i = 0; i < n; ++i) {
    const Vec3 e = program.positions[static_cast<std::size_t>(i)].normalized();
    for (int c = 0; c < 3; ++c) z(3 * i + c) = Real(e(c));
  }
  kkt.initial_multipliers(z);

  const Real norm = newton_least_squares([&](const VecX& x) { return kkt.residual(x); }, z, P, options.max_iterations,
                                         out.summary.iterations);
  out.residual = static_cast<double>(norm);
  const bool converged = norm <= converged_residual(P);
  out.summary.termination = converged ? Termination::converged : Termination::not_converged;
  out.summary.message = converged ? "first-order conditions solved to the digits asked"
                                  : "Newton stopped before the first-order conditions met 10^-(P+10)";

  ProgramTpl<Real> polished;
  for (int i = 0; i < n; ++i) {
    const Vec3T<Real> e(z(3 * i), z(3 * i + 1), z(3 * i + 2));
    polished.positions.push_back(e / e.norm());
  }
  const Real value = polish_value(criterion, polished);
  // A residual r moves the value by O(r) at most: claim only the digits it leaves untouched.
  out.digits = converged ? P : digits_left_by(norm, P);
  out.value_digits = value_text(value, out.digits);
  out.program = polished.template cast<double>();
  return out;
}

extern template PolishResult polish_kkt<Paper9Model>(const PolishOps<Paper9Model>&, const Program&,
                                                     const PolishOptions&);

}  // namespace scalcal::polish_detail
