// Theorem 7 (printable jigs, proofs/printable_jigs.md): which of the twelve jigs reach which limit,
// in every mounting. Each claim is an exact identity over the jigs' exact face normals.
#include <string>

#include "proofs/checks/check.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/jigs.hpp"

using GiNaC::ex;
namespace sym = scalcal::symbolic;
using scalcal::proofs::check;

namespace {

ex ipow(const ex& x, int e) { return e == 0 ? ex(1) : GiNaC::pow(x, e); }

long dfact(int n) { return n <= 1 ? 1 : n * dfact(n - 2); }

// E[x^i y^j z^k] on the unit sphere: 0 unless all even, else (i-1)!!(j-1)!!(k-1)!!/(i+j+k+1)!!.
ex sphere(int i, int j, int k) {
  if (i % 2 || j % 2 || k % 2) return 0;
  return ex(dfact(i - 1) * dfact(j - 1) * dfact(k - 1)) / ex(dfact(i + j + k + 1));
}

// sum over the normals of x^i y^j z^k equals N times the sphere's, for every degree 1..t.
bool design(const std::vector<sym::WeightedPoint>& pts, int t) {
  const ex n = static_cast<long>(pts.size());
  for (int d = 1; d <= t; ++d)
    for (int i = 0; i <= d; ++i)
      for (int j = 0; i + j <= d; ++j) {
        ex s = 0;
        for (const auto& p : pts) s += ipow(p.eta[0], i) * ipow(p.eta[1], j) * ipow(p.eta[2], d - i - j);
        if (!sym::is_zero_exact(s - n * sphere(i, j, d - i - j))) return false;
      }
  return true;
}

// (1/N^2) sum_ij (eta_i . eta_j)^4, the squared norm of the fourth-moment tensor.
ex fourth_norm(const std::vector<sym::WeightedPoint>& pts) {
  ex s = 0;
  for (const auto& u : pts)
    for (const auto& v : pts)
      s += GiNaC::expand(GiNaC::pow(u.eta[0] * v.eta[0] + u.eta[1] * v.eta[1] + u.eta[2] * v.eta[2], 4));
  return sym::canonical(s / static_cast<long>(pts.size() * pts.size()));
}

// T(R): h(R eta) = T(R) h(eta) for h = (x, y, z, x^2, y^2, z^2, xy, yz, zx); column c holds the
// coefficients of the rotated monomials in the monomial basis.
GiNaC::matrix representation(const GiNaC::matrix& R) {
  const GiNaC::symbol x("x"), y("y"), z("z");
  const ex v[3] = {R(0, 0) * x + R(0, 1) * y + R(0, 2) * z, R(1, 0) * x + R(1, 1) * y + R(1, 2) * z,
                   R(2, 0) * x + R(2, 1) * y + R(2, 2) * z};
  const ex rotated[9] = {v[0],        v[1],        v[2],        v[0] * v[0], v[1] * v[1],
                         v[2] * v[2], v[0] * v[1], v[1] * v[2], v[2] * v[0]};
  const ex basis[9][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0}, {0, 2, 0},
                          {0, 0, 2}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
  GiNaC::matrix T(9, 9);
  for (int r = 0; r < 9; ++r) {
    const ex e = GiNaC::expand(rotated[r]);
    for (int c = 0; c < 9; ++c)
      T(r, c) = e.coeff(x, GiNaC::ex_to<GiNaC::numeric>(basis[c][0]).to_int())
                    .coeff(y, GiNaC::ex_to<GiNaC::numeric>(basis[c][1]).to_int())
                    .coeff(z, GiNaC::ex_to<GiNaC::numeric>(basis[c][2]).to_int());
  }
  return T;
}

}  // namespace

int main() {
  // D does not depend on the mounting: h(R eta) = T(R) h(eta), so H_R = H T(R)^T and
  // det(H_R^T H_R) = det(T)^2 det(H^T H). T is a representation (T(R1 R2) = T(R1) T(R2)) and every
  // rotation is a product of turns about x and z, so det T = 1 for those two suffices. c, s stand for
  // cos and sin of a free angle, reduced with s^2 = 1 - c^2.
  {
    const GiNaC::symbol c("c"), s("s");
    const GiNaC::matrix Rz(3, 3, GiNaC::lst{c, -s, 0, s, c, 0, 0, 0, 1});
    const GiNaC::matrix Rx(3, 3, GiNaC::lst{1, 0, 0, 0, c, -s, 0, s, c});
    for (const auto& [R, name] : {std::pair{Rz, "z"}, std::pair{Rx, "x"}}) {
      const ex det = GiNaC::expand(representation(R).determinant());
      const ex reduced =
          GiNaC::expand(det.subs(GiNaC::pow(s, 2) == 1 - GiNaC::pow(c, 2), GiNaC::subs_options::algebraic));
      check(GiNaC::expand(reduced - 1).is_zero(),
            (std::string("det T(R) = 1 for every turn about ") + name + ": D is the same in every mounting").c_str());
    }
  }
  const ex d_limit = ex(61509375) / 4;
  const ex target_a = sym::canonical((ex(225) - 96 * GiNaC::sqrt(ex(2))) / 441);  // 1/3 - 4b + 30b^2 at b_A
  check(sym::is_zero_exact(target_a - sym::canonical(ex(1) / 3 - 4 * ((3 - GiNaC::sqrt(ex(2))) / 21) +
                                                     30 * GiNaC::pow((3 - GiNaC::sqrt(ex(2))) / 21, 2))),
        "the A optimum (E[x^2 y^2] = (3 - sqrt 2)/21) has fourth-moment norm (225 - 96 sqrt 2)/441");
  for (const auto& j : sym::printable_jigs()) {
    const std::string name = "jig:" + j.name + ": ";
    const bool icosahedral = j.symmetry == "icosahedral";
    check(design(j.normals, 3), (name + "a 3-design (moments of degree 1-3 are the sphere's)").c_str());
    if (icosahedral) {
      check(design(j.normals, 5), (name + "a 5-design: H^T H/N is the sphere's in every mounting").c_str());
      const auto c = sym::exact_criteria(sym::moment_matrix(j.normals), static_cast<long>(j.normals.size()));
      check(sym::is_zero_exact(c.at("D").value() - d_limit),
            (name + "D = 61509375/4, the limit, in every mounting").c_str());
      // By hand at b = 1/15: A = 12 + 2/(1/3 - 3b) + 3/b = 72; E = S = 1/b = 15.
      check(sym::is_zero_exact(c.at("A").value() - 72) && sym::is_zero_exact(c.at("E").value() - 15) &&
                sym::is_zero_exact(c.at("S").value() - 15),
            (name + "A = 72, E = 15, S = 15 in every mounting: above 45+18 sqrt 2, 12, 6+3 sqrt 3").c_str());
    } else {
      ex quartic = 0;
      for (const auto& p : j.normals) quartic += ipow(p.eta[0], 4) + ipow(p.eta[1], 4) + ipow(p.eta[2], 4);
      check(!sym::is_zero_exact(quartic - ex(3 * static_cast<long>(j.normals.size())) / 5),
            (name + "not a 4-design (sum x^4+y^4+z^4 != 3N/5) in any mounting: never D's limit").c_str());
    }
    const ex own = fourth_norm(j.normals);
    check(!sym::is_zero_exact(own - target_a),
          (name + "fourth-moment norm " + sym::canonical_text(own) + " != the A optimum's: never A's limit").c_str());
    if (j.normals.size() < 9)
      check(true, (name + std::to_string(j.normals.size()) + " faces < 9 parameters: rank-deficient in every mounting")
                      .c_str());
  }
  // E's limit at the default mounting of the rhombic dodecahedron (its faces are the 12 edge positions).
  const auto& rd = sym::printable_jigs()[8];
  const auto c = sym::exact_criteria(sym::moment_matrix(rd.normals), 12);
  check(rd.name == "rhombic-dodecahedron" && sym::is_zero_exact(c.at("E").value() - 12),
        "jig:rhombic-dodecahedron: E = 12, the limit, at the default mounting");
  return scalcal::proofs::finish();
}
