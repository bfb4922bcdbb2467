// Theorem 22 (proofs/design_lp.md): no linear-programming bound of Delsarte's kind excludes a spherical
// 4-design of N >= 10 points on S^2 (repeated points allowed), so none settles N = 11, 13, 15 (the D
// limit's open cases), and Theorem 21's bound gives nothing for N >= 10.
//
// A 4-design X of N points has the distance distribution A = (1/N) sum_{i != j} delta(t_ij), of mass N - 1,
// with a_l = int P_l dA = -1 for l = 1..4 and a_l >= -1 for l >= 5 (sum_ij P_l(t_ij) >= 0). A Delsarte
// bound is a polynomial F >= 0 on [-1, 1] with Legendre coefficients F_l <= 0 for l >= 5; it gives
// N >= F(1)/F_0. The witness below is a measure with mass 9 and these constraints for N = 10: then
// 0 <= int F dA <= 9 F_0 - sum_{l>=1} F_l = 10 F_0 - F(1), so every such bound is at most 10.
// Checks: the witness's moments exactly (l = 0..4), a_l >= -1 exactly for l = 5..200, and for l > 200
// Bernstein's inequality |P_l(cos theta)| < sqrt(2 / (pi l sin theta)) (Szego, Orthogonal Polynomials,
// Theorem 7.3.3): |a_l| <= W / sqrt(l) with W >= sum_j w_j (1 - t_j^2)^(-1/4), and W^2 <= 200.
#include <iostream>
#include <vector>

#include <ginac/ginac.h>

#include "proofs/checks/check.hpp"

using GiNaC::numeric;
using scalcal::proofs::check;

namespace {

// The witness (atoms t_j in [-4/5, 9/20], weights w_j), found by SciPy's HiGHS maximising the least
// slack of a_l >= -1 over l = 5..80 on the atoms k/40, then made exact in its five largest weights.
const char* const kWitness[][2] = {{"-4/5", "154089568273/143325000000"},
                                   {"-31/40", "233349/500000"},
                                   {"-7/10", "83058378101/108675000000"},
                                   {"-3/5", "749/250000"},
                                   {"-23/40", "527621/1000000"},
                                   {"-21/40", "450269/1000000"},
                                   {"-1/2", "3447/62500"},
                                   {"-2/5", "228511/500000"},
                                   {"-3/8", "2403/200000"},
                                   {"-1/4", "5661/100000"},
                                   {"-9/40", "237389/1000000"},
                                   {"3/20", "120947/500000"},
                                   {"7/40", "84225471919/56306250000"},
                                   {"1/4", "349473/1000000"},
                                   {"11/40", "43639/250000"},
                                   {"17/40", "3101644559/2067187500"},
                                   {"9/20", "21492094471/18975000000"}};

// a_l = sum_j w_j P_l(t_j) for l = 0..n, exact (Bonnet's recurrence at each atom).
std::vector<numeric> moments(const std::vector<numeric>& t, const std::vector<numeric>& w, int n) {
  std::vector<numeric> a(static_cast<std::size_t>(n + 1), 0);
  for (std::size_t j = 0; j < t.size(); ++j) {
    numeric p0 = 1, p1 = t[j];
    a[0] += w[j];
    a[1] += w[j] * p1;
    for (int l = 1; l < n; ++l) {
      const numeric p2 = ((2 * l + 1) * t[j] * p1 - l * p0) / (l + 1);
      a[static_cast<std::size_t>(l + 1)] += w[j] * p2;
      p0 = p1;
      p1 = p2;
    }
  }
  return a;
}

// The smallest q = k/1000 with q^4 (1 - t^2) >= 1: an upper bound on (1 - t^2)^(-1/4).
numeric quarter_bound(const numeric& t) {
  const numeric r = 1 - t * t;
  numeric q(1);
  while (q.power(4) * r < 1) q += numeric(1, 1000);
  return q;
}

}  // namespace

int main() {
  constexpr int kExact = 200;
  std::vector<numeric> t, w;
  for (const auto& atom : kWitness) {
    t.emplace_back(atom[0]);
    w.emplace_back(atom[1]);
  }
  bool inside = true;
  for (std::size_t j = 0; j < t.size(); ++j)
    inside = inside && w[j] > 0 && t[j] >= numeric(-4, 5) && t[j] <= numeric(9, 20);
  check(inside, "17 atoms in [-4/5, 9/20] with positive weights");
  const std::vector<numeric> a = moments(t, w, kExact);
  check(a[0] == 9 && a[1] == -1 && a[2] == -1 && a[3] == -1 && a[4] == -1,
        "mass 9 = N - 1 and a_1 = a_2 = a_3 = a_4 = -1 exactly (a 10-point 4-design's distance distribution)");
  numeric least = a[5];
  for (int l = 5; l <= kExact; ++l) least = std::min(least, a[static_cast<std::size_t>(l)]);
  check(least > -1, "a_l > -1 for l = 5..200 (exact rationals)");
  std::cout << "  (least a_l, l = 5..200: " << GiNaC::evalf(GiNaC::ex(least)) << ")\n";
  numeric W = 0;
  for (std::size_t j = 0; j < t.size(); ++j) W += w[j] * quarter_bound(t[j]);
  check(W * W <= kExact, "W = sum_j w_j (1 - t_j^2)^(-1/4) <= sqrt(200): |a_l| < W / sqrt(l) <= 1 for l > 200");
  std::cout << "  (W <= " << GiNaC::evalf(GiNaC::ex(W)) << ")\n";
  // The remark on N = 11: with X the traceless part of eta eta^T (<X, X'> = t^2 - 1/3), the vectors
  // (1, sqrt(15/2) X, sqrt 3 eta, sqrt 2 (cos th, sin th)) have inner products k(t) + 2 cos(th - th') and
  // squared norms 11.
  const GiNaC::symbol s("t");
  const GiNaC::ex k = (15 * s * s + 6 * s - 3) / 2;
  check(GiNaC::expand(1 + GiNaC::ex(15) / 2 * (s * s - GiNaC::ex(1) / 3) + 3 * s - k).is_zero() &&
            GiNaC::expand(k.subs(s == 1) + 2 - 11).is_zero(),
        "remark (N = 11): 1 + 15/2 (t^2 - 1/3) + 3t = k(t), and k(1) + 2 = 11");
  // |k(t_ij)| = 11 |Q_ij| <= 11 Q_ii = 2: k >= min k = k(-1/5) = -9/5 always, and k <= 2 iff 15t^2 + 6t - 7 <= 0,
  // whose roots are (-3 +- sqrt 114)/15 = -0.9118, 0.5118.
  const GiNaC::ex root = (-3 + GiNaC::sqrt(GiNaC::ex(114))) / 15;
  check(GiNaC::expand(k.subs(s == GiNaC::ex(-1) / 5) + GiNaC::ex(9) / 5).is_zero() &&
            GiNaC::expand(2 * (k - 2) - (15 * s * s + 6 * s - 7)).is_zero() &&
            GiNaC::expand(15 * root * root + 6 * root - 7).is_zero(),
        "remark (N = 11): |k| <= 2 leaves t_ij in [(-3 - sqrt 114)/15, (-3 + sqrt 114)/15] = [-0.912, 0.512]");
  // The per-point view (non_attainment.md): each point of an N-point 4-design sees the other N - 1 inner
  // products with sum_j P_l(t_ij) = -1 (l = 1..4), i.e. power sums -1, (N-3)/3, -1, (N-5)/5; at N = 11 these
  // are the moments of a measure on [-1, 1] (Hankel and localising matrices positive definite).
  {
    const GiNaC::symbol n("n");
    const GiNaC::ex s1 = -1, s2 = (n - 3) / 3, s3 = -1, s4 = (n - 5) / 5, s0 = n - 1;
    const bool sums = GiNaC::expand((3 * s2 - s0) / 2 + 1).is_zero() &&
                      GiNaC::expand((5 * s3 - 3 * s1) / 2 + 1).is_zero() &&
                      GiNaC::expand((35 * s4 - 30 * s2 + 3 * s0) / 8 + 1).is_zero();
    const numeric m1(-1, 10), m2(4, 15), m3(-1, 10), m4(3, 25);  // N = 11, divided by the mass 10
    const numeric h2 = m2 - m1 * m1, h3 = m2 * m4 - m3 * m3 - m1 * (m1 * m4 - m3 * m2) + m2 * (m1 * m3 - m2 * m2);
    check(sums && h2 > 0 && h3 == numeric(121, 16875) && 1 - m2 > 0 && m2 - m4 > 0 && m1 - m3 == 0,
          "per point: power sums -1, (N-3)/3, -1, (N-5)/5; at N = 11 the Hankel minors 1, 77/300, 121/16875 and the "
          "localising matrix diag(11/15, 11/75) are positive: one point's view has no contradiction");
  }
  // Control: the same atoms with the weights of a 9-point design's mass (8, scaled) fail the moments.
  std::vector<numeric> scaled;
  for (const numeric& x : w) scaled.push_back(x * numeric(8, 9));
  const std::vector<numeric> b = moments(t, scaled, 4);
  check(!(b[1] == -1 && b[2] == -1), "control: scaled to mass 8 (N = 9) the moments are no longer -1");
  return scalcal::proofs::finish();
}
