#include "numeric/certify/certify.hpp"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include <Eigen/QR>

#include "numeric/certify/critical_point.hpp"
#include "numeric/certify/krawczyk.hpp"
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
int gauge_partner(const Program& p) {
  int best = 1;
  double far = -1;
  for (int j = 1; j < p.size(); ++j) {
    const double s = p.positions[0].normalized().cross(p.positions[j].normalized()).norm();
    if (s > far) far = s, best = j;
  }
  return best;
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

void attainment(const Program& program, CriterionKind c, const CertifyOptions& o, CertifyResult& r) {
  r.status = CertifiedStatus::attained_numerical;
  r.method = "Krawczyk on the 24 moment equations of degree <= 4";
  const bool d = criterion_name(c) == "D";
  const int n = program.size();
  const int second = d ? gauge_partner(program) : -1;
  const SphereChart chart = SphereChart::of(program, d ? 0 : -1, second);
  std::vector<int> gauge;
  if (d) gauge = {0, 1, 2 * second};
  MomentSystem all{&chart, FreeCoordinates::all_but(2 * n, gauge), optimal_b(c)};
  Eigen::VectorXd F;
  Eigen::MatrixXd J;
  all.eval<double>(Eigen::VectorXd::Zero(all.size()), F, &J);
  const double deviation = F.cwiseAbs().maxCoeff();
  if (deviation > 1e-6) {
    r.reason = "its moments of degree <= 4 differ from the symmetric optimal measure's by " + sci(Real(deviation)) +
               " (E and S have other optimal moment matrices), so the moment certificate does not apply";
    return;
  }
  if (all.size() < MomentSystem::kEquations) {
    r.reason = "the moment system is overdetermined: " + std::to_string(all.size()) + " coordinates" +
               (d ? " after the rotation gauge" : "") + " for 24 equations; only a special program can solve it" +
               (d && n == 12 ? " (the icosahedron does, exactly: proof.d_designs)" : "");
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
  const Real tolerance = pow(Real(10), -Real(o.digits - 8));
  const NewtonOutcome polished = newton(square, VecX::Zero(square.size()), tolerance);
  if (polished.residual > pow(Real(10), -Real(o.digits / 2)) || polished.displacement > 1e-6) {
    r.reason = "Newton on the moment equations did not converge near the program (residual " +
               sci(polished.residual) + ", moved " + sci(polished.displacement) + ")";
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
  if (name != "D" && name != "A") {
    r.method = "none";
    r.reason = name + " is not differentiable at its optima (a multiple eigenvalue or several active diagonal "
                      "entries); its local optimality is not certified here";
    return;
  }
  r.method = "Krawczyk on the gradient, interval Cholesky of the Hessian";
  const bool d = name == "D";
  const int n = program.size();
  const int second = d ? gauge_partner(program) : -1;
  const SphereChart chart = SphereChart::of(program, d ? 0 : -1, second);
  std::vector<int> gauge;
  if (d) gauge = {0, 1, 2 * second};
  const CriticalPointSystem system{&chart, FreeCoordinates::all_but(2 * n, gauge),
                                   d ? CriticalForm::log_det : CriticalForm::trace};
  r.unknowns = r.equations = system.size();
  const Real tolerance = pow(Real(10), -Real(o.digits - 8));
  const NewtonOutcome polished = newton(system, VecX::Zero(system.size()), tolerance);
  if (polished.residual > pow(Real(10), -Real(o.digits / 2)) || polished.displacement > 1e-4) {
    r.reason = "Newton on the gradient did not converge near the program (residual " + sci(polished.residual) +
               ", moved " + sci(polished.displacement) + "): not an optimum to certify";
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
  // Cholesky over the whole box: every Hessian in it is positive definite.
  const int m = system.size();
  for (int k = 0; k < m; ++k) {
    for (int j = 0; j < k; ++j) H(k, k) -= H(k, j) * H(k, j);
    if (!(lo(H(k, k)) > 0)) {
      r.reason = "a critical point is enclosed, but the Hessian is not proven positive definite (pivot " +
                 std::to_string(k) + "): a saddle or a degenerate minimum";
      return;
    }
    H(k, k) = sqrt(H(k, k));
    for (int i = k + 1; i < m; ++i) {
      for (int j = 0; j < k; ++j) H(i, k) -= H(i, j) * H(k, j);
      H(i, k) /= H(k, k);
    }
  }
  // Mean-value form: f(X) within f(x) + F(X) . (X - x).
  const IVecX xi = points(polished.x);
  Interval f = system.objective<Interval>(xi);
  for (int a = 0; a < m; ++a) f += FX(a) * (box->box(a) - xi(a));
  const Interval value = d ? Interval(exp(f + Interval(9) * log(Interval(n)))) : Interval(Interval(n) * f);
  const Real lo_v = lo(value), hi_v = hi(value);
  using std::floor;
  using std::log10;
  r.enclosure_digits = static_cast<int>(floor(log10(abs(lo_v) / (hi_v - lo_v))));
  const int printed = std::min(r.enclosure_digits + 2, o.digits - 5);
  r.enclosure_lo = outward(lo_v, printed, false);
  r.enclosure_hi = outward(hi_v, printed, true);
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
