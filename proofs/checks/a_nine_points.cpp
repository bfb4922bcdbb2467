// No 9-point program attains the A limit (proofs/a_nine_points.md). A is attained iff M = N M_A
// (tr M^-1 is strictly convex: one optimal moment matrix, b = (3 - sqrt 2)/21). At N = 9, H is square
// and invertible, so P = H M^-1 H^T = I: k(eta_i, eta_j) = 9 delta_ij for the kernel
// k(eta, xi) = h(eta)^T M_A^-1 h(xi). The check proves, with t = eta . xi and s = sum_k eta_k^2 xi_k^2,
//   k = 3t + (3/2)(3 + sqrt 2) t^2 + (3/2)(2 sqrt 2 - 1) s - (3/2) sqrt 2   on the sphere (GiNaC),
// so k(eta, eta) = 9 iff sigma4(eta) = x^4 + y^4 + z^4 = (1 + 2 sqrt 2)/7. Such a point has a coordinate
// with m^2 >= r+ = (1 + sqrt(2 sigma* - 1))/2 > 1/2 (sigma4 <= m^2 and sigma4 <= m^4 + (1 - m^2)^2), so it
// lies in one of six disjoint caps about +-e_x, +-e_y, +-e_z; two points in one cap have t >= 2 r+ - 1 >= 0
// and s >= r+^2, where k > 0 (MPFI). Nine points in six caps: two share one, k != 0, P != I.
#include <ginac/ginac.h>

#include "numeric/certify/interval.hpp"
#include "proofs/checks/check.hpp"
#include "proofs/checks/sphere_reduction.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"

using GiNaC::ex;
using GiNaC::symbol;
using scalcal::proofs::check;
using scalcal::proofs::on_sphere;
namespace sym = scalcal::symbolic;

namespace {

const ex s2 = GiNaC::sqrt(ex(2));
const ex closed_sigma = (1 + 2 * s2) / 7;

// Step 2: k(eta, xi) of the symmetric moment matrix with E[x^2 y^2] = b is the closed form on the sphere.
bool kernel_identity(const ex& b) {
  const GiNaC::matrix K = sym::symmetric_moment_matrix(b).inverse();
  const symbol x1("x1"), y1("y1"), z1("z1"), x2("x2"), y2("y2"), z2("z2");
  const GiNaC::matrix h1 = sym::design_row({x1, y1, z1}), h2 = sym::design_row({x2, y2, z2});
  const ex kernel = GiNaC::expand((h1.transpose().mul(K).mul(h2))(0, 0));
  const ex t = x1 * x2 + y1 * y2 + z1 * z2;
  const ex s = x1 * x1 * x2 * x2 + y1 * y1 * y2 * y2 + z1 * z1 * z2 * z2;
  const ex closed = 3 * t + ex(3) / 2 * (3 + s2) * t * t + ex(3) / 2 * (2 * s2 - 1) * s - ex(3) / 2 * s2;
  // Reduce modulo both sphere equations: z1^2 = 1 - x1^2 - y1^2, then z2^2 = 1 - x2^2 - y2^2.
  return sym::is_zero_exact(on_sphere(on_sphere(GiNaC::expand(kernel - closed), x1, y1, z1), x2, y2, z2));
}

// Step 3: the curve's sigma* agrees with the optimal moments, sigma* = 1 - 6b.
bool consistent(const ex& b) { return sym::is_zero_exact(closed_sigma - (1 - 6 * b)); }

}  // namespace

int main() {
  const ex b = (3 - s2) / 21;
  check(kernel_identity(b),
        "k(eta, xi) = 3t + 3/2 (3+sqrt2) t^2 + 3/2 (2 sqrt2 - 1) s - 3/2 sqrt2 on the sphere (M_A^-1 exact)");
  const ex sigma = closed_sigma;
  check(sym::is_zero_exact(3 + ex(3) / 2 * (3 + s2) + ex(3) / 2 * (2 * s2 - 1) * sigma - ex(3) / 2 * s2 - 9),
        "k(eta, eta) = 9 iff sigma4(eta) = (1 + 2 sqrt 2)/7 (t = 1, s = sigma4; the coefficient of s is > 0)");
  check(consistent(b), "sigma* = 1 - 6 b_A = 3 E[x^4]: consistent with the optimal moments (mean of sigma4)");
  // Controls: with E's b = 1/12 in place of b_A both fail, as they must.
  check(!kernel_identity(ex(1) / 12) && !consistent(ex(1) / 12),
        "control: with E's b = 1/12 the kernel identity and the consistency of sigma* fail");

  // The cap argument in MPFI.
  using namespace scalcal::certify_detail;
  const IntervalPrecision precision(50);
  const Interval r2 = sqrt(Interval(2)), sig = (Interval(1) + Interval(2) * r2) / Interval(7);
  const Interval root = sqrt(Interval(2) * sig - Interval(1));
  const Interval r_plus = (Interval(1) + root) / Interval(2), r_minus = (Interval(1) - root) / Interval(2);
  check(lo(Interval(2) * sig - Interval(1)) > 0 && lo(sig) > hi(r_minus),
        "2 sigma* - 1 > 0 and sigma* > r- : the largest coordinate has m^2 >= sigma* > r-, hence m^2 >= r+");
  check(lo(r_plus) > 0.5, "r+ > 1/2: one coordinate only, so the six caps m^2 >= r+ about +-e_k are disjoint");
  const Interval t_min = Interval(2) * r_plus - Interval(1), s_min = r_plus * r_plus;
  const Interval F =
      (Interval(3) + r2) * t_min * t_min + Interval(2) * t_min + (Interval(2) * r2 - Interval(1)) * s_min - r2;
  check(lo(t_min) >= 0 && lo(F) > 0,
        "two points in one cap: t >= 2r+ - 1 >= 0, s >= r+^2, so (2/3) k = (3+sqrt2) t^2 + 2t + (2sqrt2-1) s - sqrt2 "
        "> 0 (increasing in t >= 0 and in s): nine points in six caps cannot have k(eta_i, eta_j) = 0 for all i != j");
  std::cout << "  (r+ = " << mid(r_plus).str(8) << ", (2/3) k >= " << lo(F).str(6) << " for two points in one cap)\n";
  return scalcal::proofs::finish();
}
