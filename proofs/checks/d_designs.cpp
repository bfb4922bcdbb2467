// Theorem 3 (who attains the D limit): exactly the spherical 4-designs. Checks: the jigs and
// octahedral(1, 2, 0) have M/N = M_u exactly; no 9-point and no 10-point program attains it
// (the projection argument of proofs/d_equality.md, in exact arithmetic).
#include "proofs/checks/check.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"
#include "symbolic/limits.hpp"

using GiNaC::ex;
using scalcal::proofs::check;
namespace sym = scalcal::symbolic;

namespace {
bool is_uniform(const std::string& family, const std::vector<std::string>& params) {
  const auto& f = sym::find_family(family);
  const auto inst = f.instance(sym::parse_params(f, params));
  const GiNaC::matrix Mu = sym::symmetric_moment_matrix(ex(1) / 15);
  for (int r = 0; r < 9; ++r)
    for (int c = 0; c < 9; ++c)
      if (!sym::is_zero_exact(inst.M(r, c) - inst.N * Mu(r, c))) return false;
  return true;
}
// q0 + q1 sqrt(p1) + q2 sqrt(p2) with q0 != 0 and square-free p1 != p2 > 1 is never 0 (proof);
// here: the rational part must vanish for the sum to vanish.
}  // namespace

int main() {
  check(is_uniform("icosahedral", {}), "icosahedral jig (N = 20): M/N = M_u exactly");
  check(is_uniform("dodecahedral", {}), "dodecahedral jig (N = 12): M/N = M_u exactly");
  check(is_uniform("octahedral", {"axes=1", "edges=2", "diagonals=0"}),
        "octahedral(1, 2, 0) (N = 30): M/N = M_u exactly");
  check(!is_uniform("octahedral", {"axes=1", "edges=1", "diagonals=0"}),
        "octahedral(1, 1, 0) (N = 18) is not a 4-design");
  // N = 9: P = H M^-1 H^T = I, so K(t_ij) = 0 off the diagonal: 15 t^2 + 6 t - 3 = 0.
  const GiNaC::symbol t("t");
  const ex kern = (15 * t * t + 6 * t - 3) / 2;
  const ex s6 = GiNaC::sqrt(ex(6));
  const ex al = (-1 + s6) / 5, be = (-1 - s6) / 5;
  check(sym::is_zero_exact(kern.subs(t == al)) && sym::is_zero_exact(kern.subs(t == be)),
        "N = 9: the roots of K(t) = 0 are (-1 +- sqrt 6)/5");
  // A 4-design is a 1-design: sum_j t_ij = 0 for each i, i.e. 1 + n al + (8 - n) be = 0.
  bool none9 = true;
  for (int n = 0; n <= 8; ++n) {
    const ex s = sym::canonical(1 + n * al + (8 - n) * be);
    // rational part 1 - 8/5 = -3/5 never vanishes, so s != 0 (1, sqrt 6 independent over Q)
    if (!s.coeff(GiNaC::sqrt(ex(6)), 0).is_equal(ex(-3) / 5) || s.is_zero()) none9 = false;
  }
  check(none9, "N = 9: 1 + n al + (8 - n) be has rational part -3/5 for every n: no 9-point 4-design");
  // N = 10: I - P = v v^T with v_i^2 = 1/10, so K(t_ij) = -+1: 15 t^2 + 6 t - 3 = -+2.
  const ex r21 = GiNaC::sqrt(ex(21));
  const ex roots[4] = {(-3 + 2 * r21) / 15, (-3 - 2 * r21) / 15, (-3 + 2 * s6) / 15, (-3 - 2 * s6) / 15};
  bool kern_ok = true;
  for (int i = 0; i < 4; ++i) {
    const ex k = sym::canonical(kern.subs(t == roots[i]));
    if (!(k.is_equal(ex(1)) || k.is_equal(ex(-1)))) kern_ok = false;
  }
  check(kern_ok, "N = 10: K(t) = +-1 exactly at t = (-3 +- 2 sqrt 21)/15, (-3 +- 2 sqrt 6)/15");
  bool none10 = true;
  for (int n1 = 0; n1 <= 9; ++n1)
    for (int n2 = 0; n1 + n2 <= 9; ++n2)
      for (int n3 = 0; n1 + n2 + n3 <= 9; ++n3) {
        const int n4 = 9 - n1 - n2 - n3;
        const ex s = sym::canonical(1 + n1 * roots[0] + n2 * roots[1] + n3 * roots[2] + n4 * roots[3]);
        const ex rational = s.subs(GiNaC::lst{GiNaC::sqrt(ex(21)) == 0, GiNaC::sqrt(ex(6)) == 0});
        if (!rational.is_equal(ex(-4) / 5)) none10 = false;
      }
  check(none10, "N = 10: every row sum 1 + sum_j t_ij has rational part -4/5: no 10-point 4-design");
  return scalcal::proofs::finish();
}
