#include "numeric/certify/certify.hpp"

#include <chrono>
#include <cmath>
#include <algorithm>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "numeric/certify/critical_point.hpp"
#include "numeric/certify/eigenvalue_kkt.hpp"
#include "numeric/certify/pentagonal_match.hpp"
#include "numeric/certify/krawczyk.hpp"
#include "numeric/certify/minimax_kkt.hpp"
#include "numeric/certify/moment_system.hpp"
#include "numeric/criteria/evaluation.hpp"

namespace scalcal {

std::string_view status_text(CertifiedStatus s) {
  switch (s) {
    case CertifiedStatus::attained_proven: return "limit attained, proven";
    case CertifiedStatus::attained_numerical: return "limit attained, numerical";
    case CertifiedStatus::missed_local_optimum: return "missed, certified local optimum";
    case CertifiedStatus::missed_numerical: return "missed, numerical";
  }
  return "";
}

namespace {

using namespace certify_detail;

std::string sci(const Real& x, int digits = 3) {
  std::ostringstream s;
  s << std::scientific << std::setprecision(digits - 1) << static_cast<double>(x);
  return s.str();
}

// E[x^2 y^2] of the symmetric optimal measure (proofs/aes_limits.md), enclosed.
Interval optimal_b(CriterionKind c) {
  const std::string_view name = criterion_name(c);
  if (name == "D") return Interval(1) / Interval(15);
  if (name == "A") return Interval(1) / (Interval(9) + Interval(3) * sqrt(Interval(2)));
  if (name == "E") return Interval(1) / Interval(12);
  return (Interval(2) - sqrt(Interval(3))) / Interval(3);
}

// For D, rotations leave the criterion alone: u, v of position 0 and u of the position farthest
// from its axis are held (SphereChart::of aims that u along e0 x e_second).
struct Gauge {
  SphereChart chart;
  std::vector<int> held;  // full chart indices held at 0
};

Gauge gauge_for(const Program& p, bool rotations) {
  if (!rotations) return {SphereChart::of(p), {}};
  int second = 1;
  double far = -1;
  for (int j = 1; j < p.size(); ++j) {
    const double s = p.positions[0].normalized().cross(p.positions[j].normalized()).norm();
    if (s > far) far = s, second = j;
  }
  return {SphereChart::of(p, 0, second), {0, 1, 2 * second}};
}

// Newton from the computed program: the stopping residual, and why a run does not count as converged
// near the program (empty when it does).
Real newton_tolerance(const CertifyOptions& o) { return pow(Real(10), -Real(o.digits - 8)); }

std::string newton_failure(const NewtonOutcome& n, const Real& moved, double max_move, const CertifyOptions& o) {
  if (n.residual <= pow(Real(10), -Real(o.digits / 2)) && moved <= max_move) return "";
  return "did not converge near the program (residual " + sci(n.residual) + ", moved " + sci(moved) + ")";
}

// Prints an enclosure bound rounded outward: widening by one unit of the last printed digit
// covers the decimal rounding of the conversion.
std::string outward(const Real& x, int digits, bool up) {
  using std::floor;
  using std::log10;
  const Real e = floor(log10(abs(x)));
  const Real unit = pow(Real(10), e - Real(digits - 1));
  return (up ? Real(x + unit) : Real(x - unit)).str(digits, std::ios::scientific);
}

// Cholesky over an interval matrix: true when every matrix in it is positive definite.
bool positive_definite(IMatX H) {
  const Eigen::Index m = H.rows();
  for (Eigen::Index k = 0; k < m; ++k) {
    for (Eigen::Index j = 0; j < k; ++j) H(k, k) -= H(k, j) * H(k, j);
    if (!(lo(H(k, k)) > 0)) return false;
    H(k, k) = sqrt(H(k, k));
    for (Eigen::Index i = k + 1; i < m; ++i) {
      for (Eigen::Index j = 0; j < k; ++j) H(i, k) -= H(i, j) * H(k, j);
      H(i, k) /= H(k, k);
    }
  }
  return true;
}

void set_enclosure(const Interval& value, const CertifyOptions& o, CertifyResult& r) {
  const Real lo_v = lo(value), hi_v = hi(value);
  using std::floor;
  using std::log10;
  r.enclosure_digits = static_cast<int>(floor(log10(abs(lo_v) / (hi_v - lo_v))));
  const int printed = std::min(r.enclosure_digits + 2, o.digits - 5);
  r.enclosure_lo = outward(lo_v, printed, false);
  r.enclosure_hi = outward(hi_v, printed, true);
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

// Finsler's lemma over a box: H + rho G^T G positive definite for one rho in 1, 10, ..., 1e8 proves
// H positive definite on the kernel of G (the second-order sufficient condition of a KKT point).
bool positive_on_kernel(const IMatX& H, const IMatX& GtG) {
  for (double rho = 1; rho <= 1e8; rho *= 10)
    if (positive_definite(IMatX(H + Interval(rho) * GtG))) return true;
  return false;
}

VecX to_real(const Eigen::VectorXd& x) {
  VecX out(x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) out(k) = Real(x(k));
  return out;
}

// S at a miss: the KKT system of min s subject to K_rr <= s (minimax_kkt.hpp), enclosed by
// Krawczyk; then strict complementarity (every mu_r > 0), the other entries strictly below s, and
// H + rho G G^T positive definite over the box: by Finsler's lemma the second-order sufficient
// condition (H positive definite on the directions that keep the active entries level).
void s_local_optimum(const Program& program, const CertifyOptions& o, CertifyResult& r) {
  r.method = "Krawczyk on the KKT system of the active diagonal entries, interval Cholesky of H + rho G G^T";
  const int n = program.size();
  const Gauge gauge = gauge_for(program, false);
  MinimaxKktSystem system{&gauge.chart, FreeCoordinates::all_but(2 * n, gauge.held), {}};
  const int m = system.coordinates.size();
  const Eigen::VectorXd x0 = Eigen::VectorXd::Zero(m);
  const auto K0 = system.inverse_information<double>(x0);
  const double top = K0.diagonal().maxCoeff();
  for (int q = 0; q < 9; ++q)
    if (K0(q, q) >= top * (1 - 1e-7)) system.active.push_back(q);
  const int na = static_cast<int>(system.active.size());
  // Weights: the least-squares balance of the active gradients, summing to 1.
  Eigen::VectorXd start(system.size());
  start << x0, top, Eigen::VectorXd::Constant(na, 1.0 / na);
  Eigen::VectorXd F;
  Eigen::MatrixXd J;
  system.eval<double>(start, F, &J);
  const Eigen::VectorXd mu = balanced_multipliers(J.block(0, m + 1, m, na), Eigen::VectorXd::Ones(na), 1);
  if (mu.minCoeff() <= 0) {
    r.reason = "the gradients of the " + std::to_string(na) +
               " active diagonal entries do not balance with positive weights: not a strict KKT point of S";
    return;
  }
  start.tail(na) = mu;
  r.unknowns = r.equations = system.size();
  const VecX start_real = to_real(start);
  const NewtonOutcome polished = newton(system, start_real, newton_tolerance(o));
  const Real moved = (polished.x.head(m) - start_real.head(m)).cwiseAbs().maxCoeff();
  if (const std::string failure = newton_failure(polished, moved, 1e-4, o); !failure.empty()) {
    r.reason = "Newton on the KKT system " + failure;
    return;
  }
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
  for (int q = 0; q < 9; ++q)
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
  const IMatX GGt = times(G, IMatX(G.transpose()));
  if (!positive_on_kernel(H, GGt)) {
    r.reason = "a KKT point is enclosed, but the Hessian is not proven positive definite on the level directions";
    return;
  }
  set_enclosure(Interval(n) * box->box(m), o, r);
  r.status = CertifiedStatus::missed_local_optimum;
  r.radius = sci(moved + box->radius);
  r.reason = "a strict local minimum (" + std::to_string(na) + " active diagonal entries, all weights positive)";
}

// E at a miss: the smallest eigenvalue of M is multiple there, so E is not differentiable. The
// KKT system of max lambda subject to "the cluster's Schur complement R >= 0" (eigenvalue_kkt.hpp)
// is enclosed by Krawczyk; then Omega positive definite (strict complementarity, so the critical
// directions are those with dR = 0), the complementary block A22 positive definite (the other
// eigenvalues stay above lambda in the whole box), and -Hess <Omega, R> + rho J^T J positive
// definite: Finsler's lemma gives the second-order sufficient condition (no sigma term: R = 0).
void e_local_optimum(const Program& program, const CertifyOptions& o, CertifyResult& r) {
  r.method = "Krawczyk on the KKT system of the multiple smallest eigenvalue of M, interval Cholesky of "
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
  // The cluster: eigenvalues within 1e-5 of the smallest (the optimiser's double-precision optima
  // hold their clusters to about 1e-8; the next eigenvalue is well apart at the misses).
  int m = 1;
  while (m < 9 && w(m) <= w(0) * (1 + 1e-5)) ++m;
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
  const NewtonOutcome polished = newton(system, start_real, newton_tolerance(o));
  const Real moved = (polished.x.head(nx) - start_real.head(nx)).cwiseAbs().maxCoeff();
  if (const std::string failure = newton_failure(polished, moved, 1e-4, o); !failure.empty()) {
    r.reason = "Newton on the KKT system of " + cluster + " " + failure;
    return;
  }
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
  const IMatX JtJ = times(IMatX(Jc.transpose()), Jc);
  if (!positive_on_kernel(H, JtJ)) {
    r.reason = "a KKT point is enclosed (" + cluster +
               "), but the Hessian is not proven positive definite on the directions that keep the cluster";
    return;
  }
  set_enclosure(Interval(n) / box->box(nx), o, r);
  r.status = CertifiedStatus::missed_local_optimum;
  r.radius = sci(moved + box->radius);
  r.reason = "a strict local minimum (" + cluster + ", its multiplier positive definite)";
}

void attainment(const Program& program, CriterionKind c, const CertifyOptions& o, CertifyResult& r) {
  r.status = CertifiedStatus::attained_numerical;
  r.method = "Krawczyk on the 24 moment equations of degree <= 4";
  const bool d = criterion_name(c) == "D";
  const int n = program.size();
  const Gauge gauge = gauge_for(program, d);
  const SphereChart& chart = gauge.chart;
  MomentSystem all{&chart, FreeCoordinates::all_but(2 * n, gauge.held), optimal_b(c)};
  Eigen::VectorXd F;
  Eigen::MatrixXd J;
  all.eval<double>(Eigen::VectorXd::Zero(all.size()), F, &J);
  const double deviation = F.cwiseAbs().maxCoeff();
  if (deviation > 1e-6) {
    r.reason = "its moments of degree <= 4 differ from the symmetric optimal measure's by " + sci(Real(deviation)) +
               " (E and S have other optimal moment matrices), so the moment certificate does not apply";
    return;
  }
  if (all.size() < MomentSystem::kEquations && d && n == 12) {
    if (const auto radius = radius_to_pentagonal_design(program, chart)) {
      r.status = CertifiedStatus::attained_proven;
      r.method = "fit of the pentagonal 4-designs (two poles, two turned pentagons at +-1/sqrt 5), enclosed in MPFI";
      r.radius = sci(*radius);
      r.reason = "an exact member of the pentagonal family, a 4-design for every pair of turns "
                 "(proof.pentagonal_designs), lies within the radius, one point per position; the moment system "
                 "itself is overdetermined at N = 12";
      return;
    }
  }
  if (all.size() < MomentSystem::kEquations) {
    r.reason = "the moment system is overdetermined: " + std::to_string(all.size()) + " coordinates" +
               (d ? " after the rotation gauge" : "") + " for 24 equations; only a special program can solve it" +
               (d && n == 12 ? " (the pentagonal 4-designs do, proof.pentagonal_designs, but this program is not within "
                                "1e-4 of one)"
                              : "");
    return;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
  const Eigen::MatrixXd R = qr.matrixR().topLeftCorner(MomentSystem::kEquations, MomentSystem::kEquations);
  const double conditioning = std::abs(R(23, 23)) / std::abs(R(0, 0));
  if (!(conditioning > 1e-6)) {
    r.reason = "the moment equations lose rank at this program (pivot ratio " + sci(Real(conditioning)) +
               "), so no square subsystem is regular there";
    return;
  }
  std::vector<bool> solve(2 * n, false);
  for (int k = 0; k < MomentSystem::kEquations; ++k) solve[all.coordinates.free[qr.colsPermutation().indices()(k)]] = true;
  std::vector<int> held;
  for (int k = 0; k < 2 * n; ++k)
    if (!solve[k]) held.push_back(k);
  const MomentSystem square{&chart, FreeCoordinates::all_but(2 * n, held), all.b};
  r.unknowns = square.size();
  r.equations = MomentSystem::kEquations;
  const NewtonOutcome polished = newton(square, VecX::Zero(square.size()), newton_tolerance(o));
  if (const std::string failure = newton_failure(polished, polished.displacement, 1e-6, o); !failure.empty()) {
    r.reason = "Newton on the moment equations " + failure;
    return;
  }
  const auto box = krawczyk(square, polished.x);
  if (!box) {
    r.reason = "no Krawczyk box passed about the polished program";
    return;
  }
  r.status = CertifiedStatus::attained_proven;
  r.radius = sci(polished.displacement + box->radius);
  r.reason = std::to_string(2 * n - r.unknowns) + " coordinates held at their computed values" +
             (d ? " (3 of them fix the rotation)" : "") + "; the exact program has M/N equal to the optimal moment matrix";
}

void local_optimum(const Program& program, CriterionKind c, const CertifyOptions& o, CertifyResult& r) {
  r.status = CertifiedStatus::missed_numerical;
  const std::string name(criterion_name(c));
  if (name == "S") return s_local_optimum(program, o, r);
  if (name == "E") return e_local_optimum(program, o, r);
  r.method = "Krawczyk on the gradient, interval Cholesky of the Hessian";
  const bool d = name == "D";
  const int n = program.size();
  const Gauge gauge = gauge_for(program, d);
  const CriticalPointSystem system{&gauge.chart, FreeCoordinates::all_but(2 * n, gauge.held),
                                   d ? CriticalForm::log_det : CriticalForm::trace};
  r.unknowns = r.equations = system.size();
  const NewtonOutcome polished = newton(system, VecX::Zero(system.size()), newton_tolerance(o));
  if (const std::string failure = newton_failure(polished, polished.displacement, 1e-4, o); !failure.empty()) {
    r.reason = "Newton on the gradient " + failure + ": not an optimum to certify";
    return;
  }
  const auto box = krawczyk(system, polished.x);
  if (!box) {
    r.reason = "no Krawczyk box passed about the critical point";
    return;
  }
  IVecX FX;
  IMatX H;
  system.eval(box->box, FX, &H);
  const int m = system.size();
  if (!positive_definite(H)) {
    r.reason = "a critical point is enclosed, but the Hessian is not proven positive definite: a saddle or a "
               "degenerate minimum";
    return;
  }
  // Mean-value form: f(X) within f(x) + F(X) . (X - x).
  const IVecX xi = points(polished.x);
  Interval f = system.objective<Interval>(xi);
  for (int a = 0; a < m; ++a) f += FX(a) * (box->box(a) - xi(a));
  const Interval value = d ? Interval(exp(f + Interval(9) * log(Interval(n)))) : Interval(Interval(n) * f);
  set_enclosure(value, o, r);
  r.status = CertifiedStatus::missed_local_optimum;
  r.radius = sci(polished.displacement + box->radius);
  r.reason = d ? "a strict local minimum up to rotation (u, v of one position and one coordinate of another held)"
               : "a strict local minimum";
}

}  // namespace

CertifyResult certify(const Program& program, CriterionKind criterion, const CertifyOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (program.size() < 9) throw std::invalid_argument("certify: a program needs at least 9 positions");
  CertifyResult r;
  r.value = criterion_value(program, criterion);
  if (!std::isfinite(r.value)) throw std::invalid_argument("certify: the program is singular (rank < 9)");
  r.limit = criterion_limit(criterion).value;
  {
    const IntervalPrecision precision(static_cast<unsigned>(options.digits));
    if (r.value / r.limit - 1 < options.attained_tolerance)
      attainment(program, criterion, options, r);
    else
      local_optimum(program, criterion, options, r);
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace scalcal
