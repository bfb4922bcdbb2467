// Distinct-point 4-designs from orbits of the cube's rotation group O (24 rotations): for any p on
// the sphere, the orbit's moments of degree <= 4 differ from the uniform ones by a multiple of
// p_x^4 + p_y^4 + p_z^4 - 3/5 (the only O-invariant harmonic of degree <= 4 is the quartic one).
// Hence the orbit of a p with p_x^4 + p_y^4 + p_z^4 = 3/5 attains the D limit at N = 24, an orbit
// with 1/2 plus the 6 axes at N = 30, and (intermediate values, proofs/certified_attainment.md)
// every N = 24k and 24k + 6.
#include <vector>

#include <ginac/ginac.h>

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

// The 24 signed permutation matrices of determinant +1, applied to p.
std::vector<sym::Point> orbit(const sym::Point& p) {
  const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
  std::vector<sym::Point> out;
  for (int k = 0; k < 6; ++k)
    for (int signs = 0; signs < 8; ++signs) {
      const int s[3] = {signs & 1 ? -1 : 1, signs & 2 ? -1 : 1, signs & 4 ? -1 : 1};
      const int parity = k < 3 ? 1 : -1;  // even or odd permutation
      if (s[0] * s[1] * s[2] * parity != 1) continue;
      out.push_back({s[0] * p[perms[k][0]], s[1] * p[perms[k][1]], s[2] * p[perms[k][2]]});
    }
  return out;
}

std::vector<sym::WeightedPoint> weighted(const std::vector<sym::Point>& points) {
  std::vector<sym::WeightedPoint> out;
  for (const auto& q : points) out.push_back({ex(1), q});
  return out;
}

bool equals_uniform(const GiNaC::matrix& M, int n) {
  const GiNaC::matrix Mu = sym::symmetric_moment_matrix(ex(1) / 15);
  for (int r = 0; r < 9; ++r)
    for (int c = 0; c < 9; ++c)
      if (!sym::is_zero_exact(M(r, c) - n * Mu(r, c))) return false;
  return true;
}

// Pairwise distinct, with a margin far above the rounding of evalf.
bool distinct(const std::vector<sym::Point>& points) {
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      double d = 0;
      for (int k = 0; k < 3; ++k)
        d += std::abs(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(points[i][k] - points[j][k])).to_double());
      if (d < 1e-6) return false;
    }
  return true;
}

}  // namespace

int main() {
  const symbol x("x"), y("y"), z("z");
  const auto generic = orbit({x, y, z});
  check(generic.size() == 24, "O has 24 rotations");
  // The general claim, for a symbolic p on the sphere.
  const GiNaC::matrix M = sym::moment_matrix(weighted(generic));
  const GiNaC::matrix Mu = sym::symmetric_moment_matrix(ex(1) / 15);
  const ex q = on_sphere(GiNaC::pow(x, 4) + GiNaC::pow(y, 4) + GiNaC::pow(z, 4) - ex(3) / 5, x, y, z);
  const ex q4 = GiNaC::expand(q).coeff(x, 4).coeff(y, 0).coeff(z, 0);
  bool proportional = true;
  for (int r = 0; r < 9 && proportional; ++r)
    for (int c = 0; c < 9 && proportional; ++c) {
      const ex diff = on_sphere(M(r, c) / 24 - Mu(r, c), x, y, z);
      const ex factor = GiNaC::expand(diff).coeff(x, 4).coeff(y, 0).coeff(z, 0) / q4;
      proportional =
          on_sphere(diff - factor * q, x, y, z).is_zero() && !factor.has(x) && !factor.has(y) && !factor.has(z);
    }
  check(proportional,
        "orbit moments / 24 - uniform moments = const * (x^4 + y^4 + z^4 - 3/5) on the sphere, entrywise");

  // N = 24: p = (sqrt((5 + sqrt 5)/10), sqrt((5 - sqrt 5)/10), 0), where x^4 + y^4 = 3/5.
  const ex s5 = GiNaC::sqrt(ex(5));
  const auto o24 = orbit({GiNaC::sqrt((5 + s5) / 10), GiNaC::sqrt((5 - s5) / 10), ex(0)});
  check(distinct(o24), "N = 24: the orbit has 24 distinct positions");
  check(equals_uniform(sym::moment_matrix(weighted(o24)), 24), "N = 24: M/N = M_u exactly (D limit attained)");

  // N = 30: p = (sqrt((3 + sqrt 5)/8), sqrt((3 - sqrt 5)/8), 1/2) (x^4 + y^4 + z^4 = 1/2) and the 6 axes.
  auto o30 = orbit({GiNaC::sqrt((3 + s5) / 8), GiNaC::sqrt((3 - s5) / 8), ex(1) / 2});
  for (int k = 0; k < 3; ++k)
    for (int s : {1, -1}) {
      sym::Point a{ex(0), ex(0), ex(0)};
      a[k] = s;
      o30.push_back(a);
    }
  check(distinct(o30), "N = 30: the orbit and the axes are 30 distinct positions");
  check(equals_uniform(sym::moment_matrix(weighted(o30)), 30), "N = 30: M/N = M_u exactly (D limit attained)");
  return scalcal::proofs::finish();
}
