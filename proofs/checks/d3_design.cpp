// A 14-point spherical 4-design with the dihedral symmetry D3 (so D is attained at N = 14), in closed
// form: the poles +-e_z and the D3-orbits of two points at heights z1, z2 with
// z1^2, z2^2 = (10 +- sqrt 35)/45 and turns phi1, phi2 with (cos 3 phi_k, sin 3 phi_k) = (C_k, S_k),
// S1^2 = t = 7261/9826 - 1431 sqrt(35)/68782, C2 = -(r1/r2)^3 C1, S2 = -(z1 r1^3)/(z2 r2^3) S1.
// D3 = <rotation by 120 degrees about z, rotation by 180 degrees about x> (6 rotations, entries in Q(sqrt 3)).
//
// Proof. (1) For a symbolic point p on the sphere, O(p) = sum over D3 of h(g p) h(g p)^T satisfies
// O(p) - 6 M_u = A1 J1(p) + A2 J2(p) + A3 J3(p) + A4 J4(p) with constant matrices A_k and the
// invariants J1 = z^2 - 1/3, J2 = z^4 - 1/5, J3 = x^3 - 3 x y^2, J4 = z (3 x^2 y - y^3): checked entry by
// entry modulo x^2 + y^2 + z^2 = 1 (the A_k solved for, then the identity verified). (2) The program's
// M = O(e_z)/3 + O(p1) + O(p2) (the pole orbit has 2 points, each reached by 3 rotations), so
// M - 14 M_u = sum_k A_k (J_k(e_z)/3 + J_k(p1) + J_k(p2)), zero when the four invariant sums vanish.
// At p = (r cos phi, r sin phi, z): J3 = r^3 cos 3 phi, J4 = z r^3 sin 3 phi (checked as the real and
// imaginary parts of (x + i y)^3). (3) The four sums: z1^2 + z2^2 = 4/9 and z1^4 + z2^4 = 2/15 exactly;
// r1^3 C1 + r2^3 C2 = 0 and z1 r1^3 S1 + z2 r2^3 S2 = 0 by the definitions; C2^2 + S2^2 = 1 exactly,
// so the angles exist; 0 < t < 1. (4) The 14 points are distinct: heights +-1, +-z1, +-z2 are six
// distinct values and each ring has three points 120 degrees apart (r > 0). Every choice of the signs
// of C1 and S1 gives a design (the relations are linear in (C, S)): the mirror images and turns.
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

// Every coefficient of a polynomial in x, y, z of degree <= 8.
std::vector<ex> coefficients(const ex& e, const symbol& x, const symbol& y, const symbol& z) {
  std::vector<ex> out;
  const ex p = GiNaC::expand(e);
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j)
      for (int k = 0; k <= 8; ++k) {
        const ex c = p.coeff(x, i).coeff(y, j).coeff(z, k);
        if (!c.is_zero()) out.push_back(c);
      }
  return out;
}

// The D3 rotations: R3^k and R3^k R2.
std::vector<GiNaC::matrix> d3() {
  const ex s3 = GiNaC::sqrt(ex(3));
  const GiNaC::matrix R3 = {{ex(-1) / 2, -s3 / 2, 0}, {s3 / 2, ex(-1) / 2, 0}, {0, 0, 1}};
  const GiNaC::matrix R2 = {{1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  std::vector<GiNaC::matrix> g;
  GiNaC::matrix P = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int k = 0; k < 3; ++k) {
    g.push_back(P);
    g.push_back(P.mul(R2));
    P = P.mul(R3);
  }
  return g;
}

// Whether O(p) - |G| M_u lies in the span of the invariants J on the sphere, entry by entry, for the
// orbit map of the group G; the coefficient matrices A_k (row-major) when it does.
bool spanned_by(const std::vector<GiNaC::matrix>& group, const std::vector<ex>& J, const symbol& x, const symbol& y,
                const symbol& z, std::vector<std::vector<ex>>& A) {
  std::vector<sym::WeightedPoint> orbit;
  for (const auto& g : group) {
    const GiNaC::matrix p = g.mul(GiNaC::matrix{{x}, {y}, {z}});
    orbit.push_back({ex(1), {p(0, 0), p(1, 0), p(2, 0)}});
  }
  const GiNaC::matrix O = sym::moment_matrix(orbit);
  const GiNaC::matrix Mu = sym::symmetric_moment_matrix(ex(1) / 15);
  const symbol a1("a1"), a2("a2"), a3("a3"), a4("a4");
  const GiNaC::lst unknowns = {a1, a2, a3, a4};
  A.assign(4, std::vector<ex>(81));
  for (int r = 0; r < 9; ++r)
    for (int c = 0; c < 9; ++c) {
      const ex rest =
          O(r, c) - static_cast<int>(group.size()) * Mu(r, c) - a1 * J[0] - a2 * J[1] - a3 * J[2] - a4 * J[3];
      GiNaC::lst equations;
      for (const ex& e : coefficients(on_sphere(rest, x, y, z), x, y, z)) equations.append(e == 0);
      const ex solution = GiNaC::lsolve(equations, unknowns);
      if (solution.nops() != 4 || !sym::is_zero_exact(on_sphere(rest.subs(solution), x, y, z))) return false;
      for (int k = 0; k < 4; ++k) A[k][9 * r + c] = unknowns.op(k).subs(solution);
    }
  return true;
}

// The invariant sums of step (3) for heights z1^2, z2^2 (J1, J2) and the circle condition of the turns
// for S1^2 = t: all zero for the design.
bool sums_vanish(const ex& z1s, const ex& z2s) {
  return sym::is_zero_exact(ex(1) / 3 * (1 - ex(1) / 3) + (z1s - ex(1) / 3) + (z2s - ex(1) / 3)) &&
         sym::is_zero_exact(ex(1) / 3 * (1 - ex(1) / 5) + (z1s * z1s - ex(1) / 5) + (z2s * z2s - ex(1) / 5));
}
bool turns_exist(const ex& z1s, const ex& z2s, const ex& t) {
  const ex r1_6 = GiNaC::pow(1 - z1s, 3), r2_6 = GiNaC::pow(1 - z2s, 3);
  return sym::is_zero_exact(r1_6 * ((1 - t) * z2s + z1s * t) - r2_6 * z2s);
}

}  // namespace

int main() {
  const symbol x("x"), y("y"), z("z");
  const std::vector<GiNaC::matrix> group = d3();
  bool closed = true;  // each element orthogonal with determinant 1
  for (const auto& g : group) {
    const GiNaC::matrix I = g.mul(g.transpose());
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) closed = closed && sym::is_zero_exact(I(i, j) - (i == j ? 1 : 0));
    closed = closed && sym::is_zero_exact(g.determinant() - 1);
  }
  check(closed, "the six D3 elements are rotations (R R^T = I, det R = 1)");

  // (1) O(p) - 6 M_u in the span of the four invariants on the sphere, entry by entry.
  const std::vector<ex> J = {z * z - ex(1) / 3, GiNaC::pow(z, 4) - ex(1) / 5, x * x * x - 3 * x * y * y,
                             z * (3 * x * x * y - y * y * y)};
  std::vector<std::vector<ex>> A;
  const bool spanned = spanned_by(group, J, x, y, z, A);
  check(spanned,
        "O(p) - 6 M_u = sum_k A_k J_k(p) on the sphere, A_k constant (J = z^2-1/3, z^4-1/5, "
        "x^3-3xy^2, z(3x^2y-y^3))");
  bool used = false;  // the identity is not vacuous: the m = 3 invariants enter M
  for (int e = 0; e < 81; ++e) used = used || !A[2][e].is_zero() || !A[3][e].is_zero();
  check(used, "the m = 3 invariants x^3-3xy^2 and z(3x^2y-y^3) enter M (A_3, A_4 nonzero)");

  // At p = (r cos phi, r sin phi, z): x^3 - 3xy^2 + i (3x^2y - y^3) = (x + iy)^3 = r^3 e^{3 i phi}.
  const ex cube = GiNaC::expand(GiNaC::pow(x + GiNaC::I * y, 3));
  check(GiNaC::expand(cube - J[2] - GiNaC::I * (3 * x * x * y - y * y * y)).is_zero(),
        "J3 = Re (x+iy)^3 = r^3 cos 3phi and J4 = z Im (x+iy)^3 = z r^3 sin 3phi");

  // (3) The invariant sums.
  const ex s35 = GiNaC::sqrt(ex(35));
  const ex z1s = (10 + s35) / 45, z2s = (10 - s35) / 45;  // z1^2, z2^2
  check(sums_vanish(z1s, z2s),
        "J1: J1(e_z)/3 + J1(p1) + J1(p2) = (2/3)/3 + z1^2 + z2^2 - 2/3 = 0 (E[z^2] = 1/3); "
        "J2: (4/5)/3 + z1^4 + z2^4 - 2/5 = 0 (E[z^4] = 1/5)");
  const ex t = ex(7261) / 9826 - ex(1431) * s35 / 68782;  // S1^2
  // C2^2 + S2^2 = (r1/r2)^6 (C1^2 + (z1/z2)^2 S1^2) = 1, times r2^6 z2^2:
  check(turns_exist(z1s, z2s, t), "C2^2 + S2^2 = 1: (r1^6 ((1-t) z2^2 + z1^2 t) = r2^6 z2^2, exact in Q(sqrt 35))");
  // 0 < t < 1 and 0 < z2^2 < z1^2 < 1 by rational bounds on sqrt 35 (5.916 < sqrt 35 < 5.9161).
  const GiNaC::numeric lo_s("5.916"), hi_s("5.9161");
  check(lo_s * lo_s < 35 && hi_s * hi_s > 35, "5.916 < sqrt 35 < 5.9161");
  const GiNaC::numeric t_lo = GiNaC::numeric(7261, 9826) - GiNaC::numeric(1431, 68782) * hi_s;
  const GiNaC::numeric t_hi = GiNaC::numeric(7261, 9826) - GiNaC::numeric(1431, 68782) * lo_s;
  check(t_lo > 0 && t_hi < 1, "0 < t < 1: (C1, S1) = (sqrt(1-t), sqrt t) lies on the unit circle");
  const GiNaC::numeric z2_lo = (10 - hi_s) / 45, z1_hi = (10 + hi_s) / 45, z1_lo = (10 + lo_s) / 45,
                       z2_hi = (10 - lo_s) / 45;
  check(z2_lo > 0 && z2_hi < z1_lo && z1_hi < 1,
        "0 < z2^2 < z1^2 < 1: heights +-1, +-z1, +-z2 are six distinct values, r1, r2 > 0 (14 distinct points)");

  // Controls: the same checks fail, as they must, for a wrong height, a wrong t, and the cyclic group C3
  // (rotations about z only) in place of D3, whose orbits leave more invariants than these four.
  check(!sums_vanish(z1s + ex(1) / 100, z2s), "control: a height off by 1/100 in z1^2 breaks the moment sums");
  check(!turns_exist(z1s, z2s, t + ex(1) / 1000), "control: t off by 1/1000 gives no turns (C2^2 + S2^2 != 1)");
  std::vector<GiNaC::matrix> c3;
  for (std::size_t k = 0; k < group.size(); k += 2) c3.push_back(group[k]);  // R3^k
  std::vector<std::vector<ex>> unused;
  check(c3.size() == 3 && !spanned_by(c3, J, x, y, z, unused),
        "control: the C3 orbit map is not in the span of the four invariants (more invariants survive)");
  return scalcal::proofs::finish();
}
