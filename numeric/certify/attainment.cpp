// The attainment certificate (attainment.hpp): the moment equations of moment_system.hpp, square
// after column-pivoted QR picks 24 chart coordinates, enclosed by Krawczyk; or the family fits.
#include "numeric/certify/attainment.hpp"

#include <cmath>

#include <Eigen/QR>

#include "numeric/certify/d3_match.hpp"
#include "numeric/certify/moment_system.hpp"
#include "numeric/certify/pentagonal_match.hpp"

namespace scalcal::certify_detail {

namespace {

// Why a program whose moments are `deviation` off the symmetric optimal measure's is not certified.
std::string deviation_reason(const CertifyTarget& t, double deviation) {
  const std::string off =
      "its moments of degree <= 4 differ from those of the symmetric optimal measure by " + sci(Real(deviation));
  if (t.unique_moments)
    return off + "; that moment matrix is the only optimal one for " + t.name +
           " (strictly convex), so the program is near the limit, not at it, and too far (over 1e-6) for the "
           "moment certificate to find the exact program";
  return off + "; for " + t.name +
         " that moment matrix is sufficient, not necessary (the criterion is not "
         "strictly convex), so the moment certificate does not apply";
}

// D at N = 12: the exact pentagonal 4-design the program is near, if any.
bool pentagonal(const Program& program, AttainmentOutcome& a) {
  auto exact = pentagonal_design_near(program);
  if (!exact) return false;
  a.proven = true;
  a.exact = std::move(*exact);
  a.method = "fit of the pentagonal 4-designs (two poles, two turned pentagons at +-1/sqrt 5), enclosed in MPFI";
  a.reason =
      "an exact member of the pentagonal family, a 4-design for every pair of turns "
      "(proof.pentagonal_designs), lies within the radius, one point per position; the moment system "
      "itself is overdetermined at N = 12";
  return true;
}

// D at N = 14: the exact D3-symmetric 4-design the program is near, if any.
bool dihedral(const Program& program, AttainmentOutcome& a) {
  auto exact = d3_design_near(program);
  if (!exact) return false;
  a.proven = true;
  a.exact = std::move(*exact);
  a.method =
      "fit of the D3-symmetric 14-point 4-design (closed form: poles and two D3-orbits at heights "
      "z^2 = (10 +- sqrt 35)/45), enclosed in MPFI";
  a.reason =
      "the exact design, a 4-design by proof.d3_design, lies within the radius, one point per position; "
      "the moment equations lose rank on the 14-point designs (23 of 24)";
  return true;
}

}  // namespace

AttainmentOutcome attainment(const Program& program, const CertifyTarget& t, int digits) {
  AttainmentOutcome a;
  a.method = "Krawczyk on the 24 moment equations of degree <= 4";
  const int n = program.size();
  const Gauge gauge = gauge_for(program, t.rotations);
  const SphereChart& chart = gauge.chart;
  MomentSystem all{&chart, FreeCoordinates::all_but(2 * n, gauge.held), t.b};
  Eigen::VectorXd F;
  Eigen::MatrixXd J;
  all.eval<double>(Eigen::VectorXd::Zero(all.size()), F, &J);
  a.deviation = F.cwiseAbs().maxCoeff();
  if (a.deviation > 1e-6) {
    a.reason = deviation_reason(t, a.deviation);
    return a;
  }
  if (t.uniform_moments && t.rotations && n == 14 && dihedral(program, a)) return a;
  const bool overdetermined = all.size() < MomentSystem::kEquations;
  const bool twelve = t.uniform_moments && t.rotations && n == 12;
  if (overdetermined && twelve && pentagonal(program, a)) return a;
  if (overdetermined) {
    a.reason = "the moment system is overdetermined: " + std::to_string(all.size()) + " coordinates" +
               (t.rotations ? " after the rotation gauge" : "") + " for 24 equations; only a special program can " +
               "solve it" +
               (twelve ? " (the pentagonal 4-designs do, proof.pentagonal_designs, but this program is not within "
                         "1e-4 of one)"
                       : "");
    return a;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(J);
  const Eigen::MatrixXd R = qr.matrixR().topLeftCorner(MomentSystem::kEquations, MomentSystem::kEquations);
  const double conditioning = std::abs(R(23, 23)) / std::abs(R(0, 0));
  if (!(conditioning > 1e-6)) {
    a.reason = "the moment equations lose rank at this program (pivot ratio " + sci(Real(conditioning)) +
               "), so no square subsystem is regular there";
    return a;
  }
  std::vector<bool> solve(2 * n, false);
  for (int k = 0; k < MomentSystem::kEquations; ++k)
    solve[all.coordinates.free[qr.colsPermutation().indices()(k)]] = true;
  std::vector<int> held;
  for (int k = 0; k < 2 * n; ++k)
    if (!solve[k]) held.push_back(k);
  const MomentSystem square{&chart, FreeCoordinates::all_but(2 * n, held), all.b};
  a.unknowns = square.size();
  a.equations = MomentSystem::kEquations;
  const NewtonOutcome polished = newton(square, VecX::Zero(square.size()), newton_tolerance(digits));
  if (const std::string failure = newton_failure(polished, polished.displacement, 1e-6, digits); !failure.empty()) {
    a.reason = "Newton on the moment equations " + failure;
    return a;
  }
  const auto box = krawczyk(square, polished.x);
  if (!box) {
    a.reason = "no Krawczyk box passed about the polished program";
    return a;
  }
  a.proven = true;
  a.exact = enclosed_positions(chart, square.coordinates.full(box->box));
  a.reason = std::to_string(2 * n - a.unknowns) + " coordinates held at their computed values" +
             (t.rotations ? " (3 of them fix the rotation)" : "") +
             "; the exact program has M/N equal to the optimal moment matrix";
  return a;
}

}  // namespace scalcal::certify_detail
