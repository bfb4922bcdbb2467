// The E and S limits of the paper's model on the cap z >= c (half-angle arccos c) in closed form
// (proofs/cap_es_limits.md). With d = 1 - c, t(z) = (2z - 1 - c)/d maps [c, 1] onto [-1, 1] and
// T2 = 2 t^2 - 1 = a0 + a1 z + a2 z^2; u = (0, 0, a1, a0, a0, a0 + a2, 0, 0, 0) has u^T h = T2(t(z)) on
// the sphere, so |u^T h| <= 1 on the cap. Then for every measure on the cap
//   lambda_min(M) <= u^T M u / |u|^2 <= 1/|u|^2, so E >= E(c) = |u|^2, and
//   K_66 >= (e6^T u)^2 / u^T M u >= (a0 + a2)^2 = S(c)  (Cauchy-Schwarz), so S >= S(c).
// Equality: uniform measures on the rim, the middle circle z = (1 + c)/2 and the pole with weights in
// closed form: M_E u = u/E(c) and M_E - I/E(c) >= 0 for c >= c_E (the root of a degree-7 polynomial,
// half-angle 110.38 degrees); K_66 = S(c) and every K_rr <= K_66 for c >= -3 + 2 sqrt 2 (99.88 degrees).
// Signs of rational functions of c on an interval are proven by Sturm sequences (exact root counts).
#include <algorithm>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "proofs/checks/check.hpp"
#include "proofs/checks/sphere_reduction.hpp"
#include "proofs/checks/sturm.hpp"
#include "symbolic/exact.hpp"

using GiNaC::ex;
using GiNaC::numeric;
using GiNaC::symbol;
using scalcal::proofs::check;
using scalcal::proofs::on_sphere;
namespace sym = scalcal::symbolic;

namespace {

const symbol c("c");

int roots_in(const ex& p, const numeric& a, const numeric& b) { return scalcal::proofs::roots_in(p, c, a, b); }

// p with every factor (c - 1) divided out (the cap's c < 1 never reaches that root).
ex without_one(ex p) {
  p = GiNaC::expand(p);
  while (p.degree(c) > 0 && GiNaC::rem(p, c - 1, c).is_zero()) p = GiNaC::expand(GiNaC::quo(p, c - 1, c));
  return p;
}

// f > 0 on (lo, 1): numerator and denominator without roots there (after the factors c - 1) and f(0) > 0.
bool positive_on(const ex& f, const numeric& lo) {
  const ex g = GiNaC::normal(f);
  const ex n = without_one(GiNaC::numer(g)), d = without_one(GiNaC::denom(g));
  return roots_in(n, lo, 1) == 0 && roots_in(d, lo, 1) == 0 && GiNaC::ex_to<numeric>(g.subs(c == 0)) > 0;
}

// The moment matrix of the uniform measure on the circle at height z: a regular hexagon at radius r
// averages every trigonometric polynomial of degree <= 5 exactly; then r^2 = 1 - z^2.
GiNaC::matrix circle(const ex& z) {
  const symbol r("r");
  const ex s3 = GiNaC::sqrt(ex(3));
  const ex cs[6] = {1, ex(1) / 2, ex(-1) / 2, -1, ex(-1) / 2, ex(1) / 2};
  const ex sn[6] = {0, s3 / 2, s3 / 2, 0, -s3 / 2, -s3 / 2};
  std::vector<sym::WeightedPoint> hexagon;
  for (int j = 0; j < 6; ++j) hexagon.push_back({ex(1) / 6, {r * cs[j], r * sn[j], z}});
  GiNaC::matrix M = sym::moment_matrix(hexagon);
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j)
      M(i, j) =
          GiNaC::expand(GiNaC::expand(M(i, j)).subs(GiNaC::pow(r, 2) == 1 - z * z, GiNaC::subs_options::algebraic));
  return M;
}

bool all_zero(const GiNaC::matrix& A) {
  for (unsigned i = 0; i < A.rows(); ++i)
    for (unsigned j = 0; j < A.cols(); ++j)
      if (!GiNaC::normal(A(i, j)).is_zero()) return false;
  return true;
}

GiNaC::matrix sub(const GiNaC::matrix& A, const std::vector<int>& idx) {
  GiNaC::matrix B(idx.size(), idx.size());
  for (std::size_t i = 0; i < idx.size(); ++i)
    for (std::size_t j = 0; j < idx.size(); ++j) B(i, j) = A(idx[i], idx[j]);
  return B;
}

}  // namespace

int main() {
  const symbol x("x"), y("y"), z("z");
  const ex d = 1 - c, t = (2 * z - 1 - c) / d;
  const ex a2 = 8 / (d * d), a1 = -8 * (1 + c) / (d * d), a0 = 2 * (1 + c) * (1 + c) / (d * d) - 1;
  const GiNaC::matrix h = {{x}, {y}, {z}, {x * x}, {y * y}, {z * z}, {x * y}, {y * z}, {z * x}};
  const GiNaC::matrix u = {{0}, {0}, {a1}, {a0}, {a0}, {a0 + a2}, {0}, {0}, {0}};
  const ex uh = (u.transpose().mul(h))(0, 0);
  check(GiNaC::normal(on_sphere(GiNaC::expand(uh * d * d - (2 * t * t - 1) * d * d), x, y, z)).is_zero(),
        "u^T h = T2(t(z)) on the sphere, t = (2z - 1 - c)/(1 - c)");
  check(GiNaC::expand(1 - GiNaC::pow(2 * t * t - 1, 2) - 4 * t * t * (1 - t * t)).is_zero(),
        "1 - T2(t)^2 = 4 t^2 (1 - t^2) >= 0 for |t| <= 1, i.e. on the cap");
  const ex E = (3 * GiNaC::pow(c, 4) + 36 * GiNaC::pow(c, 3) + 194 * c * c + 260 * c + 147) / GiNaC::pow(d, 4);
  const ex S = GiNaC::pow((3 + c) / d, 4);
  check(GiNaC::normal((u.transpose().mul(u))(0, 0) - E).is_zero(),
        "|u|^2 = E(c) = (3c^4+36c^3+194c^2+260c+147)/(1-c)^4");
  check(GiNaC::normal(GiNaC::pow(a0 + a2, 2) - S).is_zero(), "(e6^T u)^2 = (a0 + a2)^2 = S(c) = ((3+c)/(1-c))^4");

  const GiNaC::matrix rim = circle(c), middle = circle((1 + c) / 2), pole = circle(ex(1));
  // E: the weights on the rim, the middle circle and the pole.
  const ex den = 3 * GiNaC::pow(c, 4) + 36 * GiNaC::pow(c, 3) + 194 * c * c + 260 * c + 147;
  const ex wE[3] = {(3 * GiNaC::pow(c, 3) + 31 * c * c + 73 * c + 53) / den,
                    4 * (3 * GiNaC::pow(c, 3) + 27 * c * c + 33 * c + 17) / den,
                    (3 * GiNaC::pow(c, 4) + 21 * GiNaC::pow(c, 3) + 55 * c * c + 55 * c + 26) / den};
  const GiNaC::matrix ME = rim.mul_scalar(wE[0]).add(middle.mul_scalar(wE[1])).add(pole.mul_scalar(wE[2]));
  check(GiNaC::normal(wE[0] + wE[1] + wE[2] - 1).is_zero(), "E: the weights sum to 1");
  const numeric minus_one(-1);
  check(positive_on(wE[0], minus_one) && positive_on(wE[1], minus_one) && positive_on(wE[2], minus_one),
        "E: the weights are positive for every c in (-1, 1)");
  check(all_zero(ME.mul(u).sub(u.mul_scalar(1 / E))), "E: M_E u = u / E(c): lambda* = 1/E(c) is an eigenvalue");

  // M_E - I/E >= 0 on [c_E, 1): the block pattern, then each block.
  GiNaC::matrix A = ME;
  for (int i = 0; i < 9; ++i) A(i, i) -= 1 / E;
  const std::vector<std::vector<int>> blocks = {{0, 8}, {1, 7}, {6}, {2, 3, 4, 5}};
  bool pattern = true;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) {
      bool same = false;
      for (const auto& b : blocks)
        same = same || (std::find(b.begin(), b.end(), i) != b.end() && std::find(b.begin(), b.end(), j) != b.end());
      if (!same) pattern = pattern && GiNaC::normal(A(i, j)).is_zero();
    }
  check(pattern, "M_E is block diagonal: {x, zx}, {y, yz}, {xy}, {z, x^2, y^2, z^2}");
  check(all_zero(sub(A, {0, 8}).sub(sub(A, {1, 7}))), "the {y, yz} block equals the {x, zx} block");
  const ex P7 = 9 * GiNaC::pow(c, 7) + 231 * GiNaC::pow(c, 6) + 1973 * GiNaC::pow(c, 5) + 7275 * GiNaC::pow(c, 4) +
                14459 * GiNaC::pow(c, 3) + 16181 * c * c + 9287 * c + 1785;
  const numeric lo_E("-7/20");  // -0.35 < c_E
  const GiNaC::matrix Bx = sub(A, {0, 8});
  const ex detBx = GiNaC::normal(Bx.determinant());
  check(roots_in(P7, lo_E, 1) == 1 && roots_in(P7, lo_E, numeric("-348/1000")) == 1 &&
            GiNaC::ex_to<numeric>(P7.subs(c == 0)) > 0,
        "c_E: P7 has one root in (-0.35, 1), in (-0.35, -0.348] (half-angle 110.38 degrees), P7(0) > 0");
  check(GiNaC::rem(GiNaC::expand(GiNaC::numer(detBx)), P7, c).is_zero() && positive_on(GiNaC::normal(detBx / P7), lo_E),
        "det of the {x, zx} block of M_E - I/E is P7 times a factor positive on (-0.35, 1)");
  check(positive_on(Bx(0, 0), lo_E), "its (x, x) entry is positive: the block is >= 0 exactly for c >= c_E");
  check(positive_on(A(6, 6), lo_E), "the {xy} entry is positive on (-0.35, 1)");
  // The 4x4 block has u4 = (a1, a0, a0, a0 + a2) in its kernel; A4 + u4 u4^T > 0 makes A4 >= 0.
  const GiNaC::matrix A4 = sub(A, {2, 3, 4, 5});
  const GiNaC::matrix u4 = {{a1}, {a0}, {a0}, {a0 + a2}};
  const GiNaC::matrix P4 = A4.add(u4.mul(u4.transpose()));
  bool minors = true;
  for (int k = 1; k <= 4; ++k) {
    std::vector<int> lead;
    for (int i = 0; i < k; ++i) lead.push_back(i);
    minors = minors && positive_on(GiNaC::normal(sub(P4, lead).determinant()), lo_E);
  }
  check(minors, "the {z, x^2, y^2, z^2} block: A4 u4 = 0 and A4 + u4 u4^T positive definite on (-0.35, 1)");
  check(GiNaC::ex_to<numeric>(P7.subs(c == numeric("-349/1000"))) < 0,
        "below c_E (at c = -0.349) the {x, zx} block has det < 0: the three-circle measure stops attaining");

  // S: the weights, K_66 = S(c), every other K_rr <= K_66 for c >= -3 + 2 sqrt 2.
  const ex wS[3] = {1 / (c + 3), 4 * (c + 1) / GiNaC::pow(c + 3, 2), (c * c + c + 2) / GiNaC::pow(c + 3, 2)};
  check(GiNaC::normal(wS[0] + wS[1] + wS[2] - 1).is_zero() && positive_on(wS[0], minus_one) &&
            positive_on(wS[1], minus_one) && positive_on(wS[2], minus_one),
        "S: the weights sum to 1 and are positive for every c in (-1, 1)");
  const GiNaC::matrix MS = rim.mul_scalar(wS[0]).add(middle.mul_scalar(wS[1])).add(pole.mul_scalar(wS[2]));
  const GiNaC::matrix Kx = sub(MS, {0, 8}).inverse(), K4 = sub(MS, {2, 3, 4, 5}).inverse();
  const ex Kxy = 1 / MS(6, 6);
  check(GiNaC::normal(K4(3, 3) - S).is_zero(), "S: K_66 (the z^2 entry) = S(c) at the three-circle measure");
  const ex cS = -3 + 2 * GiNaC::sqrt(ex(2));
  check(GiNaC::expand(cS * cS + 6 * cS + 1).is_zero(), "c_S = -3 + 2 sqrt 2 is a root of c^2 + 6c + 1");
  const numeric lo_S("-1/5");  // -0.2 < c_S
  const ex gap_yz = GiNaC::normal(S - Kx(1, 1));
  check(roots_in(without_one(GiNaC::numer(gap_yz)), lo_S, 1) == 1 &&
            positive_on(GiNaC::normal(gap_yz / (c * c + 6 * c + 1)), lo_S),
        "K_66 - K_zx,zx = (c^2 + 6c + 1) times a factor positive on (-0.2, 1): >= 0 exactly for c >= c_S");
  check(positive_on(S - Kx(0, 0), lo_S) && positive_on(S - Kxy, lo_S) && positive_on(S - K4(0, 0), lo_S) &&
            positive_on(S - K4(1, 1), lo_S),
        "K_66 > K_xx, K_xy,xy, K_zz, K_x2,x2 on (-0.2, 1) (y, yz, y^2 by the x <-> y symmetry of the measure)");
  check(all_zero(sub(MS, {0, 8}).sub(sub(MS, {1, 7}))) && GiNaC::normal(MS(3, 3) - MS(4, 4)).is_zero(),
        "S: the measure is symmetric in x <-> y");

  // The values the regions document quotes.
  auto at = [](const ex& f, const numeric& v, const ex& want) {
    return GiNaC::normal(f.subs(c == v) - want).is_zero();
  };
  check(at(E, 0, 147) && at(S, 0, 81), "hemisphere (c = 0): E = 147, S = 81");
  check(at(E, numeric(1, 2), 5283) && at(S, numeric(1, 2), 2401), "60-degree cap (c = 1/2): E = 5283, S = 2401");
  check(at(wE[0], 0, numeric(53, 147)) && at(wE[1], 0, numeric(68, 147)) && at(wS[0], 0, numeric(1, 3)) &&
            at(wS[1], 0, numeric(4, 9)),
        "hemisphere weights: E (53, 68, 26)/147, S (3, 4, 2)/9 on rim, 60-degree circle, pole");

  // Controls: with 1/1000 moved from the rim to the pole (the weights still sum to 1) the eigenvector
  // identity of E and the value of K_66 for S fail, as they must.
  const ex moved = ex(1) / 1000;
  const GiNaC::matrix ME_off =
      rim.mul_scalar(wE[0] - moved).add(middle.mul_scalar(wE[1])).add(pole.mul_scalar(wE[2] + moved));
  check(!all_zero(ME_off.mul(u).sub(u.mul_scalar(1 / E))), "control: perturbed E weights break M_E u = u / E(c)");
  const GiNaC::matrix MS_off =
      rim.mul_scalar(wS[0] - moved).add(middle.mul_scalar(wS[1])).add(pole.mul_scalar(wS[2] + moved));
  check(!GiNaC::normal(sub(MS_off, {2, 3, 4, 5}).inverse()(3, 3) - S).is_zero(),
        "control: perturbed S weights break K_66 = S(c)");
  return scalcal::proofs::finish();
}
