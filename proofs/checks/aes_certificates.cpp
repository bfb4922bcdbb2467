// Theorem 4 again, without the symmetrisation theorem: an equivalence-theorem certificate for each
// of A, E, S, i.e. a polynomial in eta that is constant on the sphere (proofs/aes_limits.md, "Direct
// certificates"). M_b is the moment matrix of the symmetric measure with E[x^2 y^2] = b.
#include <ginac/ginac.h>

#include "proofs/checks/check.hpp"
#include "proofs/checks/sphere_reduction.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"

using GiNaC::ex;
using GiNaC::symbol;
using scalcal::proofs::check;
using scalcal::proofs::on_sphere;
using scalcal::proofs::quad;
namespace sym = scalcal::symbolic;

namespace {
GiNaC::matrix diagonal(const std::vector<ex>& d) {
  GiNaC::matrix W(d.size(), d.size());
  for (std::size_t i = 0; i < d.size(); ++i) W(i, i) = d[i];
  return W;
}
}  // namespace

int main() {
  const symbol x("x"), y("y"), z("z");
  const GiNaC::matrix h = sym::design_row({x, y, z});

  // A: K = M_bA^-1; h^T K^2 h = tr K on the sphere, so tr M(xi)^-1 >= tr K - tr(K^2 (M(xi) - M_bA)) = tr K.
  const ex bA = 1 / (9 + 3 * GiNaC::sqrt(ex(2)));
  const GiNaC::matrix KA = sym::symmetric_moment_matrix(bA).inverse();
  const ex trA = KA.trace();
  check(sym::is_zero_exact(trA - (45 + 18 * GiNaC::sqrt(ex(2)))), "A: tr M_bA^-1 = 45 + 18 sqrt 2");
  check(sym::is_zero_exact(on_sphere(quad(h, KA.mul(KA)) - trA, x, y, z)),
        "A: h^T K_A^2 h = tr K_A identically on the sphere");

  // E: Ehat = 1/4 on the three cross terms, 1/8 (I - J/3) on the squares; trace 1, positive semidefinite, inside the
  // eigenvalue-1/12 space of M_{1/12}; h^T Ehat h = 1/12, so lambda_min M(xi) <= tr(Ehat M(xi)) = 1/12.
  GiNaC::matrix Ehat(9, 9);
  for (int i = 3; i < 6; ++i)
    for (int j = 3; j < 6; ++j) Ehat(i, j) = ex(1) / 8 * ((i == j ? 1 : 0) - ex(1) / 3);
  for (int i = 6; i < 9; ++i) Ehat(i, i) = ex(1) / 4;
  check(sym::is_zero_exact(Ehat.trace() - 1), "E: tr Ehat = 1");
  const GiNaC::matrix ME = sym::symmetric_moment_matrix(ex(1) / 12);
  const GiNaC::matrix residual = ME.mul(Ehat).sub(Ehat.mul_scalar(ex(1) / 12));
  bool in_space = true;
  for (unsigned i = 0; i < 9; ++i)
    for (unsigned j = 0; j < 9; ++j) in_space = in_space && sym::is_zero_exact(residual(i, j));
  check(in_space,
        "E: M_{1/12} Ehat = Ehat / 12 (Ehat lives in the eigenvalue-1/12 space; its eigenvalues 1/4, 1/8 >= 0)");
  check(sym::is_zero_exact(on_sphere(quad(h, Ehat) - ex(1) / 12, x, y, z)),
        "E: h^T Ehat h = 1/12 identically on the sphere");

  // S: weights w on the diagonal (0 on bias, q on squares, 1/3 - q on cross terms), K = M_bS^-1:
  // h^T K W K h constant on the sphere fixes q; then max_r K_rr(xi) >= tr(W M(xi)^-1) >= tr(W K) = 6 + 3 sqrt 3.
  const ex bS = (2 - GiNaC::sqrt(ex(3))) / 3;
  const GiNaC::matrix KS = sym::symmetric_moment_matrix(bS).inverse();
  const symbol q("q");
  const ex r = ex(1) / 3 - q;
  const GiNaC::matrix W = diagonal({0, 0, 0, q, q, q, r, r, r});
  const ex tS = W.mul(KS).trace();
  const ex poly = on_sphere(quad(h, KS.mul(W).mul(KS)) - tS, x, y, z);
  // The x^4 coefficient is linear in q; solve it, then the whole polynomial must vanish.
  const ex c4 = GiNaC::expand(poly).coeff(x, 4).coeff(y, 0).coeff(z, 0);
  const ex qs = GiNaC::lsolve(c4 == 0, q);
  std::cout << "  S: q = " << GiNaC::evalf(qs)
            << " (weight of each scale-factor entry; 1/3 - q on each non-orthogonality entry)\n";
  check(sym::is_zero_exact(on_sphere(poly.subs(q == qs), x, y, z)),
        "S: h^T K W K h = tr(W K) identically on the sphere");
  const double qd = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(qs)).to_double();
  check(qd >= 0 && qd <= 1.0 / 3, "S: the weights are non-negative (0 <= q <= 1/3)");
  check(sym::is_zero_exact(tS.subs(q == qs) - (6 + 3 * GiNaC::sqrt(ex(3)))), "S: tr(W K_S) = 6 + 3 sqrt 3");
  check(sym::is_zero_exact(KS(3, 3) - (6 + 3 * GiNaC::sqrt(ex(3)))),
        "S: the scale-factor diagonal entries of K_S equal the limit");
  check(sym::is_zero_exact(KS(6, 6) - (6 + 3 * GiNaC::sqrt(ex(3)))),
        "S: the non-orthogonality diagonal entries of K_S equal the limit");
  return scalcal::proofs::finish();
}
