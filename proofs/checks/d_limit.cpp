// Theorem 2 (D limit): inf N^9 det K = 61509375/4 at b = 1/15 (uniform moments), certified by
// Kiefer-Wolfowitz: h^T (M/N)^-1 h = 9 identically on the sphere; and the reproducing kernel
// h(eta)^T M_u^-1 h(xi) = (15 t^2 + 6 t - 3)/2, t = eta . xi, used by Theorem 3.
#include <ginac/ginac.h>

#include "numeric/criteria/registry.hpp"
#include "proofs/checks/check.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"

using GiNaC::ex;
using GiNaC::symbol;
using scalcal::proofs::check;
namespace sym = scalcal::symbolic;

namespace {
// Reduction modulo x^2 + y^2 + z^2 = 1 (unique form p0(x,y) + z p1(x,y)).
ex on_sphere(const ex& e, const symbol& x, const symbol& y, const symbol& z) {
  return GiNaC::expand(GiNaC::expand(e).subs(GiNaC::pow(z, 2) == 1 - x * x - y * y, GiNaC::subs_options::algebraic));
}
}  // namespace

int main() {
  const symbol b("b");
  const auto pieces = sym::criterion_pieces(scalcal::CriterionKind::D, b);
  check(
      pieces.size() == 1 && sym::is_zero_exact(pieces[0] - 81 / (GiNaC::pow(ex(1) / 3 - 3 * b, 2) * GiNaC::pow(b, 3))),
      "1/det(M/N) = 81 / ((1/3 - 3b)^2 b^3) for the symmetric measure");
  const auto lim = sym::symbolic_limit(scalcal::CriterionKind::D);
  check(sym::is_zero_exact(lim.value - ex(61509375) / 4) && sym::is_zero_exact(lim.b - ex(1) / 15),
        "minimum over b in (0, 1/9) is 61509375/4 at b = 1/15");
  // Uniform measure: z is uniform on [-1, 1] (Archimedes), E[z^2] = 1/3, E[z^4] = 1/5, and
  // E[x^2 y^2] = (1 - 3 E[x^4]) / 6 = 1/15: the D-optimal symmetric measure is the uniform one.
  const symbol t("t");
  const ex ez4 = GiNaC::integral(t, -1, 1, GiNaC::pow(t, 4) / 2).eval_integ();
  check(ez4.is_equal(ex(1) / 5) && sym::is_zero_exact((1 - 3 * ez4) / 6 - lim.b),
        "uniform sphere moments give b = 1/15");
  // numeric/limits.hpp states the same value.
  const auto stated = scalcal::criterion_limit<double>(scalcal::CriterionKind::D);
  GiNaC::parser reader;
  check(sym::is_zero_exact(reader(std::string(stated.exact)) - lim.value), "numeric/limits.hpp: D exact string agrees");
  // Kiefer-Wolfowitz: d(eta) = h^T Mu^-1 h == 9 on the sphere.
  const symbol x("x"), y("y"), z("z"), u("u"), v("v"), w("w");
  const GiNaC::matrix Mu = sym::symmetric_moment_matrix(ex(1) / 15);
  const GiNaC::matrix Ki = Mu.inverse();
  const GiNaC::matrix h = sym::design_row({x, y, z});
  const GiNaC::matrix hx = sym::design_row({u, v, w});
  const ex d = h.transpose().mul(Ki).mul(h)(0, 0);
  check(on_sphere(d - 9, x, y, z).is_zero(),
        "h(eta)^T Mu^-1 h(eta) - 9 == 0 identically on the sphere (sensitivity constant)");
  const ex kern = h.transpose().mul(Ki).mul(hx)(0, 0);
  const ex tt = x * u + y * v + z * w;
  ex diff = on_sphere(kern - (15 * tt * tt + 6 * tt - 3) / 2, x, y, z);
  diff = on_sphere(diff, u, v, w);
  check(diff.is_zero(), "h(eta)^T Mu^-1 h(xi) = (15 t^2 + 6 t - 3)/2, t = eta . xi, on the sphere");
  // Strict concavity of log det along the symmetric family is not needed for the value; the
  // uniqueness of the optimal matrix follows from strict concavity of log det (see the proof).
  return scalcal::proofs::finish();
}
