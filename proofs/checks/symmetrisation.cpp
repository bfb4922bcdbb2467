// Theorem 1 (symmetrisation): each of the 48 signed permutations g of the axes acts on h by a
// signed permutation T_g (h(g eta) = T_g h(eta) identically), so every criterion is invariant;
// and the G-average of h h^T is diag(I/3, (a-b)I + bJ, bI), a = 1/3 - 2b, on the unit sphere.
#include <algorithm>
#include <array>

#include "proofs/checks/check.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"

using GiNaC::ex;
using GiNaC::symbol;
using scalcal::proofs::check;

int main() {
  const symbol x("x"), y("y"), z("z");
  const scalcal::symbolic::Point eta{x, y, z};
  const GiNaC::matrix h = scalcal::symbolic::design_row(eta);
  std::array<int, 3> perm{0, 1, 2};
  GiNaC::matrix avg(9, 9);
  int count = 0;
  bool all_signed_perm = true, all_identity = true;
  do {
    for (int s = 0; s < 8; ++s) {
      scalcal::symbolic::Point g;
      for (int i = 0; i < 3; ++i) g[i] = ((s >> i) & 1 ? -1 : 1) * eta[perm[i]];
      const GiNaC::matrix hg = scalcal::symbolic::design_row(g);
      // Each entry of h(g eta) must be +-1 times exactly one entry of h(eta): that defines T_g.
      GiNaC::matrix T(9, 9);
      for (int r = 0; r < 9; ++r) {
        int hits = 0;
        for (int c = 0; c < 9; ++c)
          for (int sign : {1, -1})
            if (GiNaC::expand(hg(r, 0) - sign * h(c, 0)).is_zero()) T(r, c) = sign, ++hits;
        if (hits != 1) all_signed_perm = false;
      }
      // T is a signed permutation matrix: orthogonal, and h(g eta) == T h(eta).
      const GiNaC::matrix TTt = T.mul(T.transpose());
      for (int r = 0; r < 9; ++r)
        for (int c = 0; c < 9; ++c)
          if (!(TTt(r, c) - (r == c ? 1 : 0)).is_zero()) all_signed_perm = false;
      const GiNaC::matrix Th = T.mul(h);
      for (int r = 0; r < 9; ++r)
        if (!GiNaC::expand(Th(r, 0) - hg(r, 0)).is_zero()) all_identity = false;
      avg = avg.add(hg.mul(hg.transpose()));
      ++count;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  check(count == 48, "the group has 48 signed permutations");
  check(all_signed_perm, "each g acts on h by a signed permutation matrix T_g (orthogonal)");
  check(all_identity, "h(g eta) = T_g h(eta) as polynomial identities");
  // On the sphere (z^2 = 1 - x^2 - y^2) the average equals the symmetric model with
  // b = (x^2 y^2 + y^2 z^2 + z^2 x^2)/3.
  const ex b = (x * x * y * y + y * y * z * z + z * z * x * x) / 3;
  const GiNaC::matrix model = scalcal::symbolic::symmetric_moment_matrix(b);
  bool equal = true;
  for (int r = 0; r < 9; ++r)
    for (int c = 0; c < 9; ++c) {
      ex d = GiNaC::expand(avg(r, c) / 48 - model(r, c));
      d = GiNaC::expand(d.subs(GiNaC::pow(z, 2) == 1 - x * x - y * y, GiNaC::subs_options::algebraic));
      if (!d.is_zero()) equal = false;
    }
  check(equal, "G-average of h h^T = diag(I/3, (a-b)I + bJ, bI), a = 1/3 - 2b, identically on the sphere");
  // b ranges over [0, 1/9]: (x^2 - y^2)^2 >= 0 gives E[x^4] >= E[x^2 y^2], i.e. 1/3 - 2b >= b.
  check(
      GiNaC::expand(GiNaC::pow(x * x - y * y, 2) - (GiNaC::pow(x, 4) + GiNaC::pow(y, 4) - 2 * x * x * y * y)).is_zero(),
      "(x^2 - y^2)^2 = x^4 + y^4 - 2 x^2 y^2, so a >= b, b <= 1/9");
  return scalcal::proofs::finish();
}
