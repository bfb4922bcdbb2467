// The polish of the eigenvalue form (E). E = 1 / lambda_min(M/N) is not differentiable at its optimum, where lambda_min
// is a multiple eigenvalue (m = 5 at N = 9 and at the limit 12), so its first-order conditions are those of a nonsmooth
// maximum: a dual Z = U C U^T (C >= 0, trace 1) on the eigenspace U of lambda_min with tangential grad tr(Z M) = 0 at
// every position. Newton runs on the multiplicity-m form of these conditions (as in Overton's methods for eigenvalue
// optimisation), unknowns z = (eta, lambda, U, C, nu), residual
//   (M/N - lambda I) U,  U^T U - I,                 (lambda an m-fold eigenvalue, U its eigenvectors)
//   2 J_i^T Z h_i / N + 2 nu_i eta_i,  |eta_i|^2 - 1,  trace C - 1   (Z = U C U^T, C symmetric).
// Why not Z as a free 9x9 unknown with (M/N - lambda I) Z = 0: that system does not fix the
// multiplicity, and where the optimal Z has rank below m its roots branch, so Newton may slide to a
// point where lambda has split and is no longer the minimum. Why not the LL^T form Ipopt uses: L is
// singular at the optimum, where its KKT conditions degenerate. Here the system is smooth and
// square, singular by the rotations U -> U Q, C -> Q^T C Q and, at the limit, by the families of
// optimal programs and of their duals; hence Levenberg-Marquardt steps (see newton_least_squares).
// C >= 0 is not imposed during Newton (C = R R^T was tried): at the limit the nearest root may
// carry an indefinite member of the family of duals, and forcing C >= 0 then drove Newton onto the
// boundary of the cone, where it stalled at |F| ~ 1e-6. So C >= 0 is checked after convergence, by
// looking for a positive member of that family (positive_dual), together with lambda =
// lambda_min(M/N) of the polished program. Only a root that passes both is a maximum, and only then
// are all P digits claimed. m comes from the eigenvalue gaps of the double optimum; a guess that
// fails is replaced by the next best gap.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "numeric/criteria/derivatives.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/polish/newton_least_squares.hpp"
#include "numeric/polish/polish.hpp"
#include "numeric/polish/polish_ops.hpp"
#include "numeric/polish/value_text.hpp"

namespace scalcal::polish_detail {

namespace eigen_form {

template <class Model>
struct EigenConditions {
  static constexpr int P = Model::kParameters;
  using MatP = InformationT<Model, Real>;
  int n = 0;  // positions
  int m = 1;  // multiplicity of lambda_min

  int lambda_at() const { return 3 * n; }
  int u_at() const { return 3 * n + 1; }
  int c_at() const { return u_at() + P * m; }
  int nu_at() const { return c_at() + m * (m + 1) / 2; }
  int unknowns() const { return nu_at() + n; }
  int equations() const { return P * m + m * (m + 1) / 2 + 4 * n + 1; }

  PositionsT<Real> positions(const VecX& z) const {
    PositionsT<Real> eta(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) eta[static_cast<std::size_t>(i)] = Vec3T<Real>(z(3 * i), z(3 * i + 1), z(3 * i + 2));
    return eta;
  }
  MatX basis(const VecX& z) const { return Eigen::Map<const MatX>(z.data() + u_at(), P, m); }
  MatX dual(const VecX& z) const {
    MatX C(m, m);
    for (int a = 0, k = c_at(); a < m; ++a)
      for (int b = a; b < m; ++b, ++k) C(a, b) = C(b, a) = z(k);
    return C;
  }

  VecX residual(const VecX& z) const {
    const PositionsT<Real> eta = positions(z);
    const Real N(n);
    MatP A = information_matrix<Model>(eta) / N;
    A.diagonal().array() -= z(lambda_at());
    const MatX U = basis(z), C = dual(z);
    VecX F(equations());
    int k = 0;
    const MatX AU = A * U;
    for (int a = 0; a < m; ++a)
      for (int r = 0; r < P; ++r) F(k++) = AU(r, a);
    const MatX G = U.transpose() * U;
    for (int a = 0; a < m; ++a)
      for (int b = a; b < m; ++b) F(k++) = G(a, b) - Real(a == b ? 1 : 0);
    const MatP Z = U * C * U.transpose() / N;
    const PositionsT<Real> g = gradient_from_dM<Model>(eta, Z);
    for (int i = 0; i < n; ++i) {
      const auto& e = eta[static_cast<std::size_t>(i)];
      const Real nu = z(nu_at() + i);
      for (int c = 0; c < 3; ++c) F(k++) = g[static_cast<std::size_t>(i)](c) + Real(2) * nu * e(c);
    }
    for (int i = 0; i < n; ++i) F(k++) = eta[static_cast<std::size_t>(i)].squaredNorm() - Real(1);
    F(k++) = C.trace() - Real(1);
    return F;
  }

  // The duals C (trace 1) that make the positions of z stationary form an affine set: one point
  // where the optimum is isolated, a family at the limit, where Newton's minimum-norm steps may
  // stop at an indefinite member although positive ones exist. z is a maximum when the set meets
  // C >= 0; alternating projections onto it and onto {C >= delta I} look for such a member, which
  // then replaces z's dual (and nu is refitted to it). `tolerance` cuts the rank of the fit and
  // bounds how negative an eigenvalue may be.
  bool positive_dual(VecX& z, const Real& tolerance) const {
    const PositionsT<Real> eta = positions(z);
    const MatX U = basis(z);
    const Real N(n);
    std::vector<MatX> unit;  // an orthonormal basis of the symmetric m x m matrices
    std::vector<PositionsT<Real>> grads;
    for (int a = 0; a < m; ++a)
      for (int c = a; c < m; ++c) {
        MatX E = MatX::Zero(m, m);
        E(a, c) = E(c, a) = a == c ? Real(1) : Real(1) / sqrt(Real(2));
        grads.push_back(gradient_from_dM<Model>(eta, MatP(U * E * U.transpose() / N)));
        unit.push_back(E);
      }
    const int pairs = static_cast<int>(unit.size());
    MatX T = MatX::Zero(3 * n + 1, pairs);
    for (int k = 0; k < pairs; ++k) {
      for (int i = 0; i < n; ++i) {
        const Vec3T<Real>& e = eta[static_cast<std::size_t>(i)];
        const Vec3T<Real>& g = grads[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)];
        const Vec3T<Real> tangential = g - e * (e.dot(g) / e.squaredNorm());
        for (int d = 0; d < 3; ++d) T(3 * i + d, k) = tangential(d);
      }
      T(3 * n, k) = unit[static_cast<std::size_t>(k)].trace();
    }
    const Eigen::JacobiSVD<MatX> svd(T, Eigen::ComputeThinU | Eigen::ComputeFullV);
    int rank = 0;
    while (rank < svd.singularValues().size() && svd.singularValues()(rank) > tolerance * svd.singularValues()(0))
      ++rank;
    const MatX free = svd.matrixV().rightCols(pairs - rank);
    const VecX fixed =
        svd.matrixV().leftCols(rank) *
        (svd.matrixU().row(3 * n).head(rank).transpose().array() / svd.singularValues().head(rank).array()).matrix();
    auto matrix = [&](const VecX& x) {
      MatX C = MatX::Zero(m, m);
      for (int k = 0; k < pairs; ++k) C += x(k) * unit[static_cast<std::size_t>(k)];
      return C;
    };
    auto coordinates = [&](const MatX& C) {
      VecX x(pairs);
      for (int k = 0; k < pairs; ++k) x(k) = C.cwiseProduct(unit[static_cast<std::size_t>(k)]).sum();
      return x;
    };
    // The shift delta aims inside the cone, so that the affine iterate lands in it, not just near it.
    const Real delta = Real(1) / Real(100 * m);
    MatX C = dual(z);
    for (int it = 0;; ++it) {
      const Eigen::SelfAdjointEigenSolver<MatX> es(C);
      if (es.eigenvalues()(0) >= -tolerance) {
        if (it == 0) return true;  // Newton's own dual will do
        break;
      }
      if (it == 500 || (it > 0 && free.cols() == 0)) return false;
      const MatX X = es.eigenvectors() * es.eigenvalues().cwiseMax(delta).asDiagonal() * es.eigenvectors().transpose();
      C = matrix(fixed + free * (free.transpose() * coordinates(X)));
    }
    for (int a = 0, k = c_at(); a < m; ++a)
      for (int b = a; b < m; ++b, ++k) z(k) = C(a, b);
    const PositionsT<Real> g = gradient_from_dM<Model>(eta, MatP(U * C * U.transpose() / N));
    for (int i = 0; i < n; ++i) {
      const Vec3T<Real>& e = eta[static_cast<std::size_t>(i)];
      z(nu_at() + i) = -e.dot(g[static_cast<std::size_t>(i)]) / (Real(2) * e.squaredNorm());
    }
    return true;
  }

  // lambda and U from the m smallest eigenpairs; C and nu as the linear least-squares fit of
  // stationarity with trace C = 1, so Newton starts from the best dual the double optimum allows.
  VecX initial(const PositionsT<Real>& eta, const Eigen::SelfAdjointEigenSolver<MatP>& eig) const {
    VecX z = VecX::Zero(unknowns());
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < 3; ++c) z(3 * i + c) = eta[static_cast<std::size_t>(i)](c);
    z(lambda_at()) = eig.eigenvalues().head(m).mean();
    Eigen::Map<MatX>(z.data() + u_at(), P, m) = eig.eigenvectors().leftCols(m);
    const MatX U = eig.eigenvectors().leftCols(m);
    const int pairs = m * (m + 1) / 2;
    MatX L = MatX::Zero(3 * n + 1, pairs + n);
    VecX b = VecX::Zero(3 * n + 1);
    const Real N(n);
    for (int a = 0, k = 0; a < m; ++a)
      for (int c = a; c < m; ++c, ++k) {
        MatX E = MatX::Zero(m, m);
        E(a, c) = E(c, a) = Real(1);
        const PositionsT<Real> g = gradient_from_dM<Model>(eta, MatP(U * E * U.transpose() / N));
        for (int i = 0; i < n; ++i)
          for (int d = 0; d < 3; ++d) L(3 * i + d, k) = g[static_cast<std::size_t>(i)](d);
        if (a == c) L(3 * n, k) = Real(1);
      }
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) L(3 * i + d, pairs + i) = Real(2) * eta[static_cast<std::size_t>(i)](d);
    b(3 * n) = Real(1);
    const VecX x = L.completeOrthogonalDecomposition().solve(b);
    z.segment(c_at(), pairs) = x.head(pairs);
    z.segment(nu_at(), n) = x.tail(n);
    return z;
  }
};

// Multiplicities to try, best first: a multiple eigenvalue at a double optimum shows as a tight
// cluster (spread about the optimiser's tolerance) followed by a wide gap, so rank m by
// gap / spread; the floor on the spread keeps m = 1 (spread 0) from winning by default. m = P (every
// eigenvalue equal, as at the E optimum of a small model) has no next eigenvalue: its gap counts as 1.
template <class Row>
std::vector<int> multiplicity_guesses(const Row& mu) {
  std::vector<std::pair<double, int>> score;
  for (int m = 1; m <= mu.size(); ++m) {
    const double spread = static_cast<double>((mu(m - 1) - mu(0)) / mu(0));
    const double gap = m < mu.size() ? static_cast<double>((mu(m) - mu(0)) / mu(0)) : 1.0;
    if (spread < 0.1) score.emplace_back(gap / std::max(spread, 1e-8), m);
  }
  std::sort(score.begin(), score.end(), std::greater<>());
  std::vector<int> out;
  for (const auto& s : score) out.push_back(s.second);
  return out;
}

struct Attempt {
  VecX z;
  Real norm;
  Summary summary;       // converged: |F| <= 10^-(P+10)
  bool maximum = false;  // converged, lambda is lambda_min, a dual C >= 0, no worse than the start
  ProgramTpl<Real> program;
  Real E;
  int digits = 0;  // the digits of E this attempt can vouch for
};

}  // namespace eigen_form

// Runs under the caller's precision guard (W = 2P + 30 digits). Compiled once for the paper's model
// (polish_eigenvalue.cpp).
template <class Model>
PolishResult polish_eigenvalue(const PolishOps<Model>& criterion, const Program& program,
                               const PolishOptions& options) {
  using namespace eigen_form;
  using MatP = InformationT<Model, Real>;
  PolishResult out;
  out.program = program;
  const int P = std::max(options.digits, 1);
  const Real target = converged_residual(P);
  const int n = program.size();
  PositionsT<Real> eta;
  for (const auto& p : program.positions) eta.push_back(p.cast<Real>().normalized());  // unit at W digits
  const Eigen::SelfAdjointEigenSolver<MatP> eig(MatP(information_matrix<Model>(eta) / Real(n)));
  if (!(eig.eigenvalues()(0) > 0)) {  // rank < P: E is infinite, there is nothing to polish
    out.residual = std::nan("");
    out.value_digits = "inf";
    out.summary.message = "rank-deficient program: E is infinite";
    return out;
  }
  const Real start_E = polish_value(criterion, ProgramTpl<Real>{eta});

  std::vector<Attempt> attempts;
  for (int m : multiplicity_guesses(eig.eigenvalues())) {
    if (attempts.size() >= 3) break;
    EigenConditions<Model> kkt{n, m};
    Attempt a;
    a.z = kkt.initial(eta, eig);
    a.norm = newton_least_squares([&](const VecX& x) { return kkt.residual(x); }, a.z, P, options.max_iterations,
                                  a.summary.iterations, true);
    out.summary.iterations += a.summary.iterations;
    for (const auto& v : kkt.positions(a.z)) a.program.positions.push_back(v / v.norm());
    a.E = polish_value(criterion, a.program);
    a.summary.termination = a.norm <= target ? Termination::converged : Termination::not_converged;
    // First-order conditions also hold at saddles of lambda on the multiplicity-m manifold: at
    // N = 9 near E = 12.3957 Ipopt results lay 1e-6 from such a root with E lower by 1e-11. So a
    // maximum must also be no worse than the double optimum it started from.
    if (a.summary.converged() && abs(a.E * a.z(kkt.lambda_at()) - Real(1)) <= sqrt(target) &&
        a.E <= start_E * (1 + sqrt(target)) && kkt.positive_dual(a.z, sqrt(target))) {
      a.maximum = true;
      a.norm = kkt.residual(a.z).norm();  // with the dual that proves it
    }
    // A residual r moves E by O(r); a root that is not a maximum says nothing certain about the
    // optimum, so it claims no more than the digits it shares with the double optimum.
    a.digits = a.maximum ? P : digits_left_by(a.norm, P);
    if (a.summary.converged() && !a.maximum) {
      const Real apart = abs(a.E - start_E) / start_E;
      a.digits = std::min(a.digits, apart > 0 ? std::max(1, static_cast<int>(floor(-log10(apart))) - 1) : 15);
    }
    attempts.push_back(std::move(a));
    if (attempts.back().maximum) break;
  }
  const Attempt& best = *std::max_element(attempts.begin(), attempts.end(), [](const Attempt& x, const Attempt& y) {
    return x.digits != y.digits ? x.digits < y.digits : x.norm > y.norm;
  });
  out.residual = static_cast<double>(best.norm);
  out.summary.termination = best.maximum ? Termination::converged : Termination::not_converged;
  out.summary.message = best.maximum
                            ? "multiple-eigenvalue conditions solved, with a positive semidefinite dual"
                            : "no root passed the checks of a maximum; digits limited to what the residual vouches for";
  out.digits = best.digits;
  out.value_digits = value_text(best.E, out.digits);
  out.program = best.program.cast<double>();
  return out;
}

extern template PolishResult polish_eigenvalue<Paper9Model>(const PolishOps<Paper9Model>&, const Program&,
                                                            const PolishOptions&);

}  // namespace scalcal::polish_detail
