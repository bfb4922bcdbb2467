// Theorem 25 (proofs/thermal_product.md), checked with GiNaC only (independent of numeric/thermal): the
// Kronecker identities behind the product, the interval's D-optimal designs for k = 1..6, its A, E, S
// designs for k = 1, 2 and its E and S designs for k = 3 by their equivalence theorems in exact arithmetic,
// and paper9's thermal limits.
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "proofs/checks/check.hpp"

using GiNaC::ex;
using GiNaC::matrix;
using GiNaC::numeric;
using GiNaC::symbol;
using scalcal::proofs::check;

namespace {

const symbol t("t");

matrix kron(const matrix& a, const matrix& b) {
  matrix out(a.rows() * b.rows(), a.cols() * b.cols());
  for (unsigned i = 0; i < a.rows(); ++i)
    for (unsigned j = 0; j < a.cols(); ++j)
      for (unsigned p = 0; p < b.rows(); ++p)
        for (unsigned q = 0; q < b.cols(); ++q) out(i * b.rows() + p, j * b.cols() + q) = a(i, j) * b(p, q);
  return out;
}

matrix symbolic_matrix(const std::string& name, unsigned n, bool symmetric) {
  matrix m(n, n);
  for (unsigned i = 0; i < n; ++i)
    for (unsigned j = 0; j < n; ++j)
      m(i, j) = symmetric && j < i ? m(j, i) : ex(symbol(name + std::to_string(i) + std::to_string(j)));
  return m;
}

matrix column(const std::vector<ex>& v) {
  matrix m(static_cast<unsigned>(v.size()), 1);
  for (unsigned i = 0; i < v.size(); ++i) m(i, 0) = v[i];
  return m;
}

ex quad(const matrix& v, const matrix& q) { return GiNaC::expand(v.transpose().mul(q).mul(v)(0, 0)); }

// Part 1: (h (x) f)^T (A (x) B) (h (x) f) = (h^T A h)(f^T B f); det(A (x) B) = det A^2 det B^3 for A
// 3x3 and B 2x2 (the powers are the other factor's size); (A (x) B)^-1 = A^-1 (x) B^-1.
void kronecker_identities() {
  const matrix A = symbolic_matrix("a", 3, true), B = symbolic_matrix("b", 2, true);
  const matrix h = column({symbol("h0"), symbol("h1"), symbol("h2")}), f = column({symbol("f0"), symbol("f1")});
  const matrix hf = kron(h, f);
  check(GiNaC::expand(quad(hf, kron(A, B)) - quad(h, A) * quad(f, B)).is_zero(),
        "(h (x) f)^T (A (x) B) (h (x) f) = (h^T A h)(f^T B f)");
  check(GiNaC::expand(kron(A, B).determinant() - GiNaC::pow(A.determinant(), 2) * GiNaC::pow(B.determinant(), 3))
            .is_zero(),
        "det(A (x) B) = det(A)^2 det(B)^3 for A 3x3, B 2x2");
  const matrix a = matrix(2, 2, GiNaC::lst{2, 1, 1, 3}), b = matrix(2, 2, GiNaC::lst{5, 2, 2, 1});
  const matrix diff = kron(a, b).inverse().sub(kron(a.inverse(), b.inverse()));
  bool zero = true;
  for (unsigned i = 0; i < 4; ++i)
    for (unsigned j = 0; j < 4; ++j) zero = zero && GiNaC::normal(diff(i, j)).is_zero();
  check(zero, "(A (x) B)^-1 = A^-1 (x) B^-1 (so trace, eigenvalues and diagonal of K multiply)");
}

matrix powers(int k) {
  std::vector<ex> f;
  for (int j = 0; j <= k; ++j) f.push_back(GiNaC::pow(t, j));
  return column(f);
}

// p = c * s^2 * (1 - t^2) * t^(2e) for a constant c > 0 and some polynomial s (so p >= 0 on [-1, 1]):
// p divided exactly by (1 - t^2) t^(2e), the quotient q made square-free-tested as c * gcd(q, q')^2.
bool nonnegative_on_interval(const ex& p, int e) {
  const ex base = GiNaC::expand((1 - t * t) * GiNaC::pow(t, 2 * e));
  ex q;
  if (!GiNaC::divide(GiNaC::expand(p), base, q)) return false;
  q = GiNaC::expand(q);
  if (q.degree(t) == 0) return GiNaC::ex_to<numeric>(q) > 0;
  const ex s = GiNaC::expand(GiNaC::gcd(q, q.diff(t)));
  const ex c = q.lcoeff(t) / GiNaC::pow(s.lcoeff(t), 2);
  return GiNaC::is_a<numeric>(c) && GiNaC::ex_to<numeric>(c) > 0 && GiNaC::expand(q - c * s * s).is_zero();
}

ex legendre(int k) {
  ex p0 = 1, p1 = t;
  if (k == 0) return p0;
  for (int n = 2; n <= k; ++n) {
    const ex p2 = GiNaC::expand(((2 * n - 1) * t * p1 - (n - 1) * p0) / n);
    p0 = p1;
    p1 = p2;
  }
  return p1;
}

// Part 2: the Lobatto design's information matrix from the moments of its nodes, written here as
// symmetric functions: E[t^m] = ((-1)^m + 1 + sum over roots r of P_k' of r^m) / (k + 1), the power sums
// from the resultant-free route of Newton's identities (coefficients of P_k' made monic).
matrix lobatto_information(int k) {
  const ex d = GiNaC::expand(legendre(k).diff(t));
  const int n = d.degree(t);
  std::vector<ex> c;
  for (int i = n; i >= 0; --i) c.push_back(d.coeff(t, i) / d.coeff(t, n));
  std::vector<ex> p(static_cast<std::size_t>(2 * k + 1), 0);
  p[0] = n;
  for (int m = 1; m <= 2 * k; ++m) {
    ex s = m <= n ? ex(m) * c[static_cast<std::size_t>(m)] : ex(0);
    for (int i = 1; i <= std::min(m - 1, n); ++i)
      s += c[static_cast<std::size_t>(i)] * p[static_cast<std::size_t>(m - i)];
    p[static_cast<std::size_t>(m)] = GiNaC::expand(-s);
  }
  matrix M(static_cast<unsigned>(k + 1), static_cast<unsigned>(k + 1));
  for (int i = 0; i <= k; ++i)
    for (int j = 0; j <= k; ++j)
      M(static_cast<unsigned>(i), static_cast<unsigned>(j)) =
          ((i + j) % 2 == 0 ? 2 : 0) + p[static_cast<std::size_t>(i + j)];
  return M.mul_scalar(ex(1) / (k + 1));
}

std::vector<ex> interval_d_values() {
  std::vector<ex> out{0};
  for (int k = 1; k <= 6; ++k) {
    const matrix M = lobatto_information(k);
    const ex variance = quad(powers(k), M.inverse());
    const ex gap = GiNaC::normal(k + 1 - variance);
    // The check of part 2: k + 1 - f^T M^-1 f = c (1 - t^2) P_k'(t)^2, c > 0.
    check(nonnegative_on_interval(gap, 0),
          ("k = " + std::to_string(k) + ": k + 1 - f^T M^-1 f = c (1 - t^2) s(t)^2, c > 0 (Lobatto design D-optimal)")
              .c_str());
    ex q;
    const bool divides =
        GiNaC::divide(GiNaC::expand(gap), GiNaC::expand((1 - t * t) * GiNaC::pow(legendre(k).diff(t), 2)), q);
    check(divides && GiNaC::expand(q).degree(t) == 0,
          ("k = " + std::to_string(k) + ": the square is P_k'(t)^2").c_str());
    out.push_back(GiNaC::normal(1 / M.determinant()));
    std::cout << "        D_1(k = " << k << ") = " << out.back() << "\n";
  }
  return out;
}

matrix design_information(int k, const std::vector<ex>& points, const std::vector<ex>& weights) {
  matrix M(static_cast<unsigned>(k + 1), static_cast<unsigned>(k + 1));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const matrix f = GiNaC::ex_to<matrix>(ex(powers(k)).subs(t == points[i]));
    M = M.add(f.mul(f.transpose()).mul_scalar(weights[i]));
  }
  return M;
}

// Part 3, k = 3: E and S on the Chebyshev points -1, -1/2, 1/2, 1, where T_3 = 4 t^3 - 3 t reaches +-1 and
// 1 - T_3^2 = (1 - t^2) (4 t^2 - 1)^2.
void interval_es_cubic() {
  const matrix f3 = powers(3);
  const ex half = ex(1) / 2;
  const matrix E = design_information(3, {-1, -half, half, 1}, {ex(19) / 150, ex(28) / 75, ex(28) / 75, ex(19) / 150});
  const matrix u = column({0, -3, 0, 4});  // T_3's coefficients, |u|^2 = 25
  check(E.mul(u) == u.mul_scalar(ex(1) / 25),
        "k = 3, E: (0, -3, 0, 4) is an eigenvector of M for 1/25 on -1, -1/2, 1/2, 1 with weights 19/150, 28/75");
  // The other three eigenvalues exceed 1/25: the characteristic polynomial divided by (x - 1/25), shifted to
  // x = 1/25 + s, is real-rooted (M symmetric), so by Descartes its roots are all positive iff its four
  // coefficients alternate in sign.
  ex q;
  const ex cp = GiNaC::expand(E.charpoly(t));
  const bool divides = GiNaC::divide(cp, t - ex(1) / 25, q);
  const ex shifted = GiNaC::expand(q.subs(t == ex(1) / 25 + t));
  bool alternate = shifted.degree(t) == 3;
  for (int i = 0; i < 3 && alternate; ++i)
    alternate = (shifted.coeff(t, i) * shifted.coeff(t, i + 1)).info(GiNaC::info_flags::negative);
  check(divides && alternate, "k = 3, E: M's other eigenvalues exceed 1/25 (the smallest simple)");
  const ex uf = u.transpose().mul(f3)(0, 0);
  check(nonnegative_on_interval(ex(1) / 25 - GiNaC::pow(uf, 2) / 25, 0),
        "k = 3, E: 1/25 - (u^T f)^2 / |u|^2 = (1 - t^2)(4 t^2 - 1)^2 / 25 >= 0 (E_1 = 25)");

  const matrix S = design_information(3, {-1, -half, half, 1}, {ex(1) / 6, ex(1) / 3, ex(1) / 3, ex(1) / 6}).inverse();
  check(S(0, 0) == 3 && S(1, 1) == 11 && S(2, 2) == 8 && S(3, 3) == 16,
        "k = 3, S: the variances are 3, 11, 8, 16 on -1, -1/2, 1/2, 1 with weights 1/6, 1/3 (largest at t^3 alone)");
  const ex e3 = S(3, 0) + S(3, 1) * t + S(3, 2) * t * t + S(3, 3) * t * t * t;  // 4 T_3
  check(nonnegative_on_interval(16 - GiNaC::pow(e3, 2), 0),
        "k = 3, S: 16 - (e_4^T M^-1 f)^2 = 16 (1 - t^2)(4 t^2 - 1)^2 >= 0 (S_1 = 16)");
}

// Part 3.
void interval_aes() {
  const matrix f1 = powers(1), f2 = powers(2);
  const matrix M1 = design_information(1, {-1, 1}, {ex(1) / 2, ex(1) / 2});
  check(M1 == matrix(2, 2, GiNaC::lst{1, 0, 0, 1}), "k = 1: +-1 with weights 1/2 give M_1 = I");
  check(nonnegative_on_interval(2 - quad(f1, M1), 0), "k = 1, A: 2 - f^T M^-2 f >= 0 (A_1 = 2)");
  check(nonnegative_on_interval(1 - quad(f1, M1) / 2, 0), "k = 1, E and S: 1 - f^T (I/2) f >= 0 (E_1 = S_1 = 1)");

  const matrix A = design_information(2, {-1, 0, 1}, {ex(1) / 4, ex(1) / 2, ex(1) / 4}).inverse();
  check(A.trace() == 8, "k = 2, A: tr M^-1 = 8 on -1, 0, 1 with weights 1/4, 1/2, 1/4");
  check(nonnegative_on_interval(8 - quad(f2, A.mul(A)), 1), "k = 2, A: 8 - f^T M^-2 f = c t^2 (1 - t^2), c > 0");
  check(A(0, 0) == 2 && A(1, 1) == 2 && A(2, 2) == 4, "k = 2, S: the variances are 2, 2, 4 (largest at t^2 alone)");
  const ex e2 = A(2, 0) + A(2, 1) * t + A(2, 2) * t * t;
  check(nonnegative_on_interval(4 - GiNaC::pow(e2, 2), 1), "k = 2, S: 4 - (e_3^T M^-1 f)^2 >= 0 (S_1 = 4)");

  const matrix E = design_information(2, {-1, 0, 1}, {ex(1) / 5, ex(3) / 5, ex(1) / 5});
  const matrix v = column({1, 0, -2});
  const matrix Ev = E.mul(v);
  check(Ev == v.mul_scalar(ex(1) / 5), "k = 2, E: (1, 0, -2) is an eigenvector of M for 1/5");
  const ex cp = GiNaC::expand(E.charpoly(t));
  const ex roots = GiNaC::expand((t - ex(1) / 5) * (t - ex(2) / 5) * (t - ex(6) / 5));
  check(GiNaC::expand(cp - roots).is_zero() || GiNaC::expand(cp + roots).is_zero(),  // charpoly's sign convention
        "k = 2, E: M's eigenvalues are 1/5, 2/5, 6/5 (the smallest simple)");
  const ex vf = v.transpose().mul(f2)(0, 0);  // 1 - 2 t^2, and |v|^2 = 5
  check(nonnegative_on_interval(ex(1) / 5 - GiNaC::pow(vf, 2) / 5, 1),
        "k = 2, E: 1/5 - (v^T f)^2 / |v|^2 >= 0 (E_1 = 5)");
  interval_es_cubic();
}

}  // namespace

int main() {
  std::cout << "Theorem 25 (proofs/thermal_product.md)\n";
  kronecker_identities();
  const std::vector<ex> d1 = interval_d_values();
  check(d1[1] == 1 && d1[2] == ex(27) / 4 && d1[3] == ex(3125) / 16,
        "D_1 = 1, 27/4, 3125/16 for k = 1, 2, 3 (the statement's)");
  interval_aes();
  // paper9's thermal D limits, part 1 with D_s = 61509375/4, P = 9: D_s^(k+1) D_1^9.
  const ex ds = ex(61509375) / 4;
  for (int k = 1; k <= 3; ++k)
    std::cout << "        paper9+T" << k
              << ": D = " << GiNaC::evalf(GiNaC::pow(ds, k + 1) * GiNaC::pow(d1[static_cast<std::size_t>(k)], 9))
              << ", bias only: "
              << GiNaC::evalf(ds * GiNaC::pow(27, k) * GiNaC::pow(d1[static_cast<std::size_t>(k)], 3)) << "\n";
  return scalcal::proofs::finish();
}
