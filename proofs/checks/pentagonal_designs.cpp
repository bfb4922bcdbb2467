// The 12-point D optima form a continuum: the two poles with two regular pentagons at heights
// +-1/sqrt 5, each turned by its own angle, are a 4-design for every pair of angles (the regular
// icosahedron is the pair 36 degrees apart). With w = e^{i theta} a ring point is
// (r (w + 1/w)/2, r (w - 1/w)/(2i), h); the k-th point of a pentagon has w = u zeta^k, zeta a
// primitive 5th root of unity. Every moment of degree <= 4 is then a Laurent polynomial in u and
// zeta; summing over k and reducing by zeta^5 = 1 and 1 + zeta + ... + zeta^4 = 0 must leave
// exactly 12 times the uniform moment matrix, for symbolic u1, u2 (so for all real angles).
#include <vector>

#include <ginac/ginac.h>

#include "proofs/checks/check.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"

using GiNaC::ex;
using GiNaC::symbol;
using scalcal::proofs::check;
namespace sym = scalcal::symbolic;

namespace {

// e as a polynomial in zeta, reduced modulo the 5th cyclotomic polynomial: coefficients of 1..zeta^3.
std::vector<ex> cyclotomic_remainder(const ex& e, const symbol& zeta) {
  const ex x = GiNaC::expand(e);
  std::vector<ex> a(5, ex(0));
  for (int j = x.ldegree(zeta); j <= x.degree(zeta); ++j) a[((j % 5) + 5) % 5] += x.coeff(zeta, j);
  // zeta^4 = -(1 + zeta + zeta^2 + zeta^3)
  return {a[0] - a[4], a[1] - a[4], a[2] - a[4], a[3] - a[4]};
}

}  // namespace

int main() {
  const symbol u1("u1"), u2("u2"), zeta("zeta");
  const ex s5 = GiNaC::sqrt(ex(5));
  const ex h = s5 / 5, r = 2 * s5 / 5;
  check(GiNaC::expand(r * r + h * h - 1).is_zero(), "r^2 + h^2 = 1: the rings lie on the sphere");
  std::vector<sym::WeightedPoint> points{{ex(1), {ex(0), ex(0), ex(1)}}, {ex(1), {ex(0), ex(0), ex(-1)}}};
  for (const auto& [u, height] : {std::pair<ex, ex>{u1, h}, std::pair<ex, ex>{u2, -h}})
    for (int k = 0; k < 5; ++k) {
      const ex w = u * GiNaC::pow(zeta, k), winv = GiNaC::pow(u, -1) * GiNaC::pow(zeta, 5 - k);
      points.push_back({ex(1), {r * (w + winv) / 2, r * (w - winv) / (2 * GiNaC::I), height}});
    }
  const GiNaC::matrix M = sym::moment_matrix(points);
  const GiNaC::matrix Mu = sym::symmetric_moment_matrix(ex(1) / 15);
  bool uniform = true;
  for (int row = 0; row < 9; ++row)
    for (int col = 0; col < 9; ++col)
      for (const ex& c : cyclotomic_remainder(M(row, col) - 12 * Mu(row, col), zeta))
        uniform = uniform && sym::is_zero_exact(c);
  check(uniform, "M = 12 M_u for every pair of angles: two poles and two turned pentagons at z = +-1/sqrt 5 attain D");

  // A non-example, so the reduction can fail: the pentagons at the icosahedron's height +-1/2 instead.
  std::vector<sym::WeightedPoint> wrong{points[0], points[1]};
  const ex h2 = ex(1) / 2, r2 = GiNaC::sqrt(ex(3)) / 2;
  for (int k = 0; k < 5; ++k) {
    const ex w = u1 * GiNaC::pow(zeta, k), winv = GiNaC::pow(u1, -1) * GiNaC::pow(zeta, 5 - k);
    wrong.push_back({ex(1), {r2 * (w + winv) / 2, r2 * (w - winv) / (2 * GiNaC::I), h2}});
    wrong.push_back({ex(1), {r2 * (w + winv) / 2, r2 * (w - winv) / (2 * GiNaC::I), -h2}});
  }
  const GiNaC::matrix Mw = sym::moment_matrix(wrong);
  bool differs = false;
  for (const ex& c : cyclotomic_remainder(Mw(5, 5) - 12 * Mu(5, 5), zeta)) differs = differs || !sym::is_zero_exact(c);
  check(differs, "at heights +-1/2 the same construction is no 4-design (E[z^4] is off)");
  return scalcal::proofs::finish();
}
