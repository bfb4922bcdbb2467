// The local-optimum certificates of local_optimum.hpp, one function per form; proofs/
// certified_attainment.md states what each proves.
#include "numeric/certify/local_optimum.hpp"

#include <algorithm>
#include <array>

#include <Eigen/Eigenvalues>

#include "numeric/certify/critical_point.hpp"
#include "numeric/certify/eigenvalue_kkt.hpp"
#include "numeric/certify/minimax_kkt.hpp"

namespace scalcal::certify_detail {

namespace {

// How far Newton may move the program and still be certifying a point "near" it.
constexpr double kMaxMove = 1e-3;

VecX to_real(const Eigen::VectorXd& x) {
  VecX out(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) out(k) = Real(x(k));
  return out;
}

Eigen::VectorXd to_double(const VecX& x) {
  Eigen::VectorXd out(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) out(k) = static_cast<double>(x(k));
  return out;
}

// Multipliers w for the gradient columns C that balance best (min |C w|) under d.w = total: the
// bordered normal equations. The Newton start of the S and E KKT systems.
Eigen::VectorXd balanced_multipliers(const Eigen::MatrixXd& C, const Eigen::VectorXd& d, double total) {
  const Eigen::Index k = C.cols();
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(k + 1, k + 1);
  B.topLeftCorner(k, k) = C.transpose() * C;
  B.block(0, k, k, 1) = d;
  B.block(k, 0, 1, k) = d.transpose();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(k + 1);
  rhs(k) = total;
  return B.fullPivLu().solve(rhs).head(k);
}

// The point Newton reached (chart coordinates in `x`'s first coordinates.size() entries), rounded.
Program polished_program(const SphereChart& chart, const FreeCoordinates& c, const VecX& x) {
  return chart.program_at(to_double(c.full(VecX(x.head(c.size())))));
}

std::vector<IPoint> box_positions(const SphereChart& chart, const FreeCoordinates& c, const IVecX& box) {
  return enclosed_positions(chart, c.full(IVecX(box.head(c.size()))));
}

// D and A: f = -log det M or tr M^-1 in the free chart coordinates; Krawczyk on the gradient,
// interval Cholesky of the Hessian over the box, the value by the mean-value form.
void smooth_optimum(const Program& program, const CertifyTarget& t, int digits, LocalOutcome& r) {
  r.method = "Krawczyk on the gradient, interval Cholesky of the Hessian";
  const bool d = t.local == LocalCertificate::log_det;
  const int n = program.size();
  const Gauge gauge = gauge_for(program, t.rotations);
  const CriticalPointSystem system{&gauge.chart, FreeCoordinates::all_but(2 * n, gauge.held),
                                   d ? CriticalForm::log_det : CriticalForm::trace};
  r.unknowns = r.equations = system.size();
  const NewtonOutcome polished = newton(system, VecX::Zero(system.size()), newton_tolerance(digits));
  if (const std::string failure = newton_failure(polished, polished.displacement, kMaxMove, digits); !failure.empty()) {
    r.reason = "Newton on the gradient " + failure + ": not an optimum to certify";
    return;
  }
  r.polished = polished_program(gauge.chart, system.coordinates, polished.x);
  const auto box = krawczyk(system, polished.x);
  if (!box) {
    r.reason = "no Krawczyk box passed about the critical point";
    return;
  }
  IVecX FX;
  IMatX H;
  system.eval(box->box, FX, &H);
  if (!positive_definite(H)) {
    r.reason =
        "a critical point is enclosed, but the Hessian is not proven positive definite: a saddle or a "
        "degenerate minimum";
    return;
  }
  // Mean-value form: f(X) within f(x) + F(X) . (X - x).
  const IVecX xi = points(polished.x);
  Interval f = system.objective<Interval>(xi);
  for (int a = 0; a < system.size(); ++a) f += FX(a) * (box->box(a) - xi(a));
  r.value = d ? Interval(exp(f + Interval(9) * log(Interval(n)))) : Interval(Interval(n) * f);
  r.optimum = box_positions(gauge.chart, system.coordinates, box->box);
  r.certified = true;
  r.reason = t.rotations ? "a strict local minimum up to rotation (u, v of one position and one coordinate of "
                           "another held)"
                         : "a strict local minimum";
}

// S at one active set (the diagonal entries within `spread` of the largest): the KKT system of
// min s subject to K_rr <= s (minimax_kkt.hpp), enclosed by Krawczyk; then strict complementarity
// (every mu_r > 0), the other entries strictly below s, and H + rho G G^T positive definite over the
// box: by Finsler's lemma the second-order sufficient condition.
void max_diagonal_optimum(const Program& program, const CertifyTarget& t, int digits, double spread, LocalOutcome& r) {
  r.method = "Krawczyk on the KKT system of the active diagonal entries, interval Cholesky of H + rho G G^T";
  const int n = program.size();
  const Gauge gauge = gauge_for(program, false);
  MinimaxKktSystem system{&gauge.chart, FreeCoordinates::all_but(2 * n, gauge.held), {}};
  const int m = system.coordinates.size();
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(m);
  const auto K0 = system.inverse_information<double>(x0);
  double top = K0(t.rows.front(), t.rows.front());
  for (int q : t.rows) top = std::max(top, K0(q, q));
  for (int q : t.rows)
    if (K0(q, q) >= top * (1 - spread)) system.active.push_back(q);
  const int na = static_cast<int>(system.active.size());
  Eigen::VectorXd start(system.size());
  start << x0, top, Eigen::VectorXd::Constant(na, 1.0 / na);
  Eigen::VectorXd F;
  Eigen::MatrixXd J;
  system.eval<double>(start, F, &J);
  const Eigen::VectorXd mu = balanced_multipliers(J.block(0, m + 1, m, na), Eigen::VectorXd::Ones(na), 1);
  if (mu.minCoeff() <= 0) {
    r.reason = "the gradients of the " + std::to_string(na) +
               " active diagonal entries do not balance with positive weights: not a strict KKT point of " + t.name;
    return;
  }
  start.tail(na) = mu;
  r.unknowns = r.equations = system.size();
  const VecX start_real = to_real(start);
  const NewtonOutcome polished = newton(system, start_real, newton_tolerance(digits));
  const Real moved = (polished.x.head(m) - start_real.head(m)).cwiseAbs().maxCoeff();
  if (const std::string failure = newton_failure(polished, moved, kMaxMove, digits); !failure.empty()) {
    r.reason = "Newton on the KKT system of " + std::to_string(na) + " active entries " + failure;
    return;
  }
  r.polished = polished_program(gauge.chart, system.coordinates, polished.x);
  const auto box = krawczyk(system, polished.x);
  if (!box) {
    r.reason = "no Krawczyk box passed about the KKT point (" + std::to_string(na) + " active entries)";
    return;
  }
  for (int q = 0; q < na; ++q)
    if (!(lo(box->box(m + 1 + q)) > 0)) {
      r.reason = "a KKT point is enclosed, but a weight is not proven positive";
      return;
    }
  const Square9<Interval> K = system.inverse_information<Interval>(box->box);
  for (int q : t.rows)
    if (std::find(system.active.begin(), system.active.end(), q) == system.active.end() &&
        !(hi(K(q, q)) < lo(box->box(m)))) {
      r.reason = "a KKT point is enclosed, but an inactive diagonal entry is not proven below the active ones";
      return;
    }
  IVecX FX;
  IMatX JX;
  system.eval(box->box, FX, &JX);
  const IMatX H = JX.topLeftCorner(m, m);
  const IMatX G = JX.block(0, m + 1, m, na);
  if (!positive_on_kernel(H, times(G, IMatX(G.transpose())))) {
    r.reason = "a KKT point is enclosed, but the Hessian is not proven positive definite on the level directions";
    return;
  }
  r.value = Interval(n) * box->box(m);
  r.optimum = box_positions(gauge.chart, system.coordinates, box->box);
  r.certified = true;
  r.reason = "a strict local minimum (" + std::to_string(na) + " active diagonal entries, all weights positive)";
}

// E at one eigenvalue cluster (within `spread` of the smallest): the KKT system of max lambda
// subject to "the cluster's Schur complement R >= 0" (eigenvalue_kkt.hpp) enclosed by Krawczyk;
// then Omega positive definite (strict complementarity), the complementary block A22 positive
// definite (the other eigenvalues stay above lambda in the whole box), and -Hess <Omega, R> +
// rho J^T J positive definite: Finsler's lemma gives the second-order sufficient condition.
void max_eigenvalue_optimum(const Program& program, int digits, double spread, LocalOutcome& r) {
  r.method =
      "Krawczyk on the KKT system of the multiple smallest eigenvalue of M, interval Cholesky of "
      "-Hess <Omega, R> + rho J^T J";
  const int n = program.size();
  const Gauge gauge = gauge_for(program, false);
  EigenvalueKktSystem system{&gauge.chart, FreeCoordinates::all_but(2 * n, gauge.held), 1, {}};
  const int nx = system.free_size();
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(nx);
  const Eigen::Matrix<double, 9, 9> M0 = assemble_information<double>(gauge.chart, system.coordinates.full(x0));
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>> eigen(M0);
  const Eigen::VectorXd w = eigen.eigenvalues();
  system.basis = eigen.eigenvectors();
  int m = 1;
  while (m < 9 && w(m) <= w(0) * (1 + spread)) ++m;
  system.multiplicity = m;
  const int k = system.pairs();
  Eigen::VectorXd start(system.size());
  start << x0, w.head(m).mean(), Eigen::VectorXd::Zero(k);
  Eigen::VectorXd F;
  Eigen::MatrixXd J;
  system.eval<double>(start, F, &J);
  // Omega: the least-squares balance of the cluster's gradients, normalised by the lambda equation.
  start.tail(k) = balanced_multipliers(J.block(0, nx + 1, nx, k), J.block(nx, nx + 1, 1, k).transpose(), -1);
  r.unknowns = r.equations = system.size();
  const std::string cluster = "an eigenvalue of multiplicity " + std::to_string(m);
  const VecX start_real = to_real(start);
  const NewtonOutcome polished = newton(system, start_real, newton_tolerance(digits));
  const Real moved = (polished.x.head(nx) - start_real.head(nx)).cwiseAbs().maxCoeff();
  if (const std::string failure = newton_failure(polished, moved, kMaxMove, digits); !failure.empty()) {
    r.reason = "Newton on the KKT system of " + cluster + " " + failure;
    return;
  }
  r.polished = polished_program(gauge.chart, system.coordinates, polished.x);
  const auto box = krawczyk(system, polished.x);
  if (!box) {
    r.reason = "no Krawczyk box passed about the KKT point (" + cluster + ")";
    return;
  }
  IVecX FX;
  IMatX JX;
  EigenvalueKktSystem::Parts<Interval> parts;
  system.eval(box->box, FX, &JX, &parts);
  if (!positive_definite(parts.omega)) {
    r.reason = "a KKT point is enclosed (" + cluster + "), but its multiplier is not proven positive definite";
    return;
  }
  if (!positive_definite(parts.A22)) {
    r.reason = "a KKT point is enclosed, but the other eigenvalues are not proven above the cluster";
    return;
  }
  const IMatX H = -JX.topLeftCorner(nx + 1, nx + 1);
  const IMatX Jc = JX.block(nx + 1, 0, k, nx + 1);
  if (!positive_on_kernel(H, times(IMatX(Jc.transpose()), Jc))) {
    r.reason = "a KKT point is enclosed (" + cluster +
               "), but the Hessian is not proven positive definite on the directions that keep the cluster";
    return;
  }
  r.value = Interval(n) / box->box(nx);
  r.optimum = box_positions(gauge.chart, system.coordinates, box->box);
  r.certified = true;
  r.reason = "a strict local minimum (" + cluster + ", its multiplier positive definite)";
}

}  // namespace

LocalOutcome local_optimum(const Program& program, const CertifyTarget& t, int digits) {
  LocalOutcome r;
  switch (t.local) {
    case LocalCertificate::none:
      r.reason = "no local-optimum certificate exists for criterion " + t.name;
      return r;
    case LocalCertificate::log_det:
    case LocalCertificate::trace:
      smooth_optimum(program, t, digits, r);
      return r;
    case LocalCertificate::max_diagonal:
    case LocalCertificate::max_eigenvalue: {
      // The active set (the cluster) is read off the program at a relative spread; a program moved
      // off its optimum spreads them, so wider spreads are tried until one certifies. The first
      // attempt's outcome is kept when none does (its reason names the computed structure).
      const bool diagonal = t.local == LocalCertificate::max_diagonal;
      const std::array<double, 3> spreads =
          diagonal ? std::array<double, 3>{1e-7, 1e-5, 1e-3} : std::array<double, 3>{1e-5, 1e-4, 1e-3};
      LocalOutcome first;
      for (const double spread : spreads) {
        LocalOutcome attempt;
        if (diagonal)
          max_diagonal_optimum(program, t, digits, spread, attempt);
        else
          max_eigenvalue_optimum(program, digits, spread, attempt);
        if (attempt.certified) return attempt;
        if (spread == spreads[0])
          first = std::move(attempt);
        else if (!first.polished && attempt.polished)
          first.polished = attempt.polished;
      }
      return first;
    }
  }
  return r;
}

}  // namespace scalcal::certify_detail
