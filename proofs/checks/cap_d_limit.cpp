// Theorem 8 (the D limit on a cap z >= c): every computational step of proofs/cap_d_limit.md.
// Part A: the moment matrix of a measure invariant under rotations about z, its block form and its
// sensitivity d(z); part B: the three-ring family (pole weight 1/9, the reduced objective, the
// stationarity equations, their resultant and the unique root t(c)); part C: the threshold
// c* = -(1+sqrt 6)/5 and the exact optimal measure there; part D: certified enclosures of the
// limit at c = cos 30, 60, 90, 120 degrees by weak duality (exact rational arithmetic, Sturm).
// Everything is exact (GiNaC rationals, Q(sqrt 3), Q(sqrt 6)); no floating point is used for any
// claim, and the output is the same bytes on every run.
#include <ginac/ginac.h>

#include <algorithm>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "proofs/checks/check.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"

using GiNaC::ex;
using GiNaC::matrix;
using GiNaC::numeric;
using GiNaC::symbol;
using scalcal::proofs::check;
namespace sym = scalcal::symbolic;

namespace {

bool zero(const ex& e) { return sym::is_zero_exact(e); }
numeric num(const ex& e) { return GiNaC::ex_to<numeric>(GiNaC::expand(e)); }
bool is_rational(const ex& e) { return GiNaC::is_a<numeric>(e) && GiNaC::ex_to<numeric>(e).is_rational(); }
numeric pow10(int k) { return numeric(10).power(k); }
ex ipow(const ex& b, int k) {  // b^k with b^0 = 1 also for b = 0 (GiNaC leaves 0^0 undefined)
  ex r = 1;
  for (int i = 0; i < k; ++i) r *= b;
  return r;
}

// ---------------------------------------------------------------------------------------------
// Exact decimal output and rounding of rationals.

numeric floor_q(const numeric& q) {  // floor of a rational
  const numeric n = q.numer(), d = q.denom();
  numeric f = GiNaC::iquo(n, d);
  if (n.is_negative() && !GiNaC::irem(n, d).is_zero()) f -= 1;
  return f;
}
numeric ceil_q(const numeric& q) { return -floor_q(-q); }
numeric round_to(const numeric& q, int digits) { return floor_q(q * pow10(digits) + numeric(1, 2)) / pow10(digits); }

std::string int_text(const numeric& n) {
  std::ostringstream s;
  s << n;
  return s.str();
}

// q > 0 to `sig` significant digits, rounded down or up: "1.2345e+08". Exact, so an enclosure
// printed with lower rounded down and upper rounded up is still an enclosure.
std::string sci(const numeric& q, int sig, bool up) {
  int e = 0;
  while (q >= pow10(e + 1)) ++e;
  while (q < pow10(e)) --e;
  const numeric scaled = q * pow10(sig - 1 - e);
  numeric n = up ? ceil_q(scaled) : floor_q(scaled);
  if (n >= pow10(sig)) {  // 9.99..9 rounded up
    n = n / 10;
    ++e;
  }
  // Strings are built by appending: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string.
  const std::string d = int_text(n);
  std::string out(d, 0, 1);
  if (d.size() > 1) out.append(".").append(d, 1, std::string::npos);
  out.append(e < 0 ? "e-" : "e+");
  const std::string ee = std::to_string(e < 0 ? -e : e);
  if (ee.size() < 2) out.append("0");
  return out.append(ee);
}

// q rounded to k decimals (nearest), as fixed-point text: "-0.5000".
std::string fixed(const numeric& q, int k) {
  const numeric n = floor_q(GiNaC::abs(q) * pow10(k) + numeric(1, 2));
  std::string d = int_text(n);
  const auto kk = static_cast<std::size_t>(k);
  if (d.size() <= kk) d.insert(0, kk + 1 - d.size(), '0');
  std::string out(q.is_negative() ? "-" : "");
  return out.append(d, 0, d.size() - kk).append(".").append(d, d.size() - kk, std::string::npos);
}

// Exact sign of an element a + b sqrt(n) of Q(sqrt n) (n > 0 not a square); throws otherwise.
int sign_in(const ex& e, int n) {
  const ex s = GiNaC::sqrt(ex(n));
  const ex f = sym::canonical(e);
  const ex a = f.coeff(s, 0), b = f.coeff(s, 1);
  if (!is_rational(a) || !is_rational(b) || !GiNaC::expand(f - a - b * s).is_zero())
    throw std::runtime_error("sign_in: not an element of Q(sqrt n)");
  const numeric A = GiNaC::ex_to<numeric>(a), B = GiNaC::ex_to<numeric>(b);
  const int sa = A.is_zero() ? 0 : (A.is_positive() ? 1 : -1), sb = B.is_zero() ? 0 : (B.is_positive() ? 1 : -1);
  if (sa == sb || sb == 0) return sa;
  if (sa == 0) return sb;
  const numeric d = A * A - numeric(n) * B * B;  // never 0: n is not a square
  return d.is_positive() ? sa : sb;
}

// ---------------------------------------------------------------------------------------------
// Sturm sequences over Q.

std::vector<ex> sturm_chain(const ex& p, const symbol& z) {
  std::vector<ex> s{GiNaC::expand(p), GiNaC::expand(p.diff(z))};
  while (s.back().degree(z) > 0) {
    ex r = GiNaC::expand(-GiNaC::rem(s[s.size() - 2], s.back(), z));
    if (r.is_zero()) break;
    r = GiNaC::expand(r / GiNaC::abs(GiNaC::ex_to<numeric>(r.lcoeff(z))));  // a positive factor keeps the signs
    s.push_back(r);
  }
  return s;
}
int variations(const std::vector<int>& signs) {
  int v = 0, last = 0;
  for (int s : signs)
    if (s != 0) {
      if (last != 0 && s != last) ++v;
      last = s;
    }
  return v;
}
int variations_at(const std::vector<ex>& chain, const symbol& z, const numeric& a) {
  std::vector<int> signs;
  for (const auto& p : chain) {
    const numeric v = num(p.subs(z == a));
    signs.push_back(v.is_zero() ? 0 : (v.is_positive() ? 1 : -1));
  }
  return variations(signs);
}
int variations_at_infinity(const std::vector<ex>& chain, const symbol& z, int side) {
  std::vector<int> signs;
  for (const auto& p : chain) {
    const numeric lc = num(p.lcoeff(z));
    int s = lc.is_positive() ? 1 : -1;
    if (side < 0 && p.degree(z) % 2 == 1) s = -s;
    signs.push_back(s);
  }
  return variations(signs);
}
// Distinct real roots of p in (a, b), for p(a) p(b) != 0 (Sturm's theorem).
int roots_between(const ex& p, const symbol& z, const numeric& a, const numeric& b) {
  const auto chain = sturm_chain(p, z);
  return variations_at(chain, z, a) - variations_at(chain, z, b);
}
int real_roots(const ex& p, const symbol& z) {
  const auto chain = sturm_chain(p, z);
  return variations_at_infinity(chain, z, -1) - variations_at_infinity(chain, z, 1);
}

// ---------------------------------------------------------------------------------------------
// Part A: measures invariant under rotations about z.

// The mean of cos^a sin^b over a full turn: the constant term of its Fourier (Laurent) expansion.
ex circle_mean(int a, int b) {
  const symbol q("q");
  const ex e = GiNaC::expand(GiNaC::pow((q + 1 / q) / 2, a) * GiNaC::pow((q - 1 / q) / (2 * GiNaC::I), b));
  return e.coeff(q, 0);
}

// The mean of a polynomial p(x, y, z) over the circle of height z on the sphere
// (x = rho cos phi, y = rho sin phi, rho^2 = 1 - z^2): a polynomial in z.
ex ring_mean(const ex& p, const symbol& x, const symbol& y, const symbol& z) {
  const ex e = GiNaC::expand(p);
  ex out = 0;
  for (int a = 0; a <= e.degree(x); ++a)
    for (int b = 0; b <= e.degree(y); ++b) {
      if ((a + b) % 2) continue;  // odd total degree in (cos, sin): mean 0 (also by circle_mean)
      out += e.coeff(x, a).coeff(y, b) * circle_mean(a, b) * GiNaC::pow(1 - z * z, (a + b) / 2);
    }
  return GiNaC::expand(out);
}

// E_mu[p(z)] for a polynomial of degree <= 4, given m[k] = E_mu[z^k].
ex expect(const ex& p, const symbol& z, const std::vector<ex>& m) {
  const ex e = GiNaC::expand(p);
  if (e.degree(z) >= static_cast<int>(m.size())) throw std::runtime_error("expect: degree too high");
  ex out = 0;
  for (int k = 0; k <= e.degree(z); ++k) out += e.coeff(z, k) * m[static_cast<std::size_t>(k)];
  return GiNaC::expand(out);
}

struct Blocks {
  matrix H{3, 3}, B{2, 2};
  ex q;
};
Blocks blocks_of(const std::vector<ex>& m) {
  Blocks b;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b.H(i, j) = m[static_cast<std::size_t>(i + j)];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) b.B(i, j) = m[static_cast<std::size_t>(i + j)] - m[static_cast<std::size_t>(i + j + 2)];
  b.q = m[0] - 2 * m[2] + m[4];
  return b;
}

// The sensitivity d(z) = v^T H^-1 v + 2 (1-z^2) w^T B^-1 w + 2 (1-z^2)^2 / q from the blocks'
// inverses (given, so that the identity can be checked for generic symmetric inverses).
ex sensitivity(const matrix& Hi, const matrix& Bi, const ex& qi, const symbol& z) {
  const matrix v(3, 1, GiNaC::lst{1, z, z * z});
  const matrix w(2, 1, GiNaC::lst{1, z});
  const ex r = 1 - z * z;
  return v.transpose().mul(Hi).mul(v)(0, 0) + 2 * r * w.transpose().mul(Bi).mul(w)(0, 0) + 2 * r * r * qi;
}

// The moments of pole weight w1, rim weight (1-w1) alpha at z = c, circle weight (1-w1)(1-alpha) at z = t.
std::vector<ex> three_ring_moments(const ex& w1, const ex& alpha, const ex& c, const ex& t) {
  std::vector<ex> m;
  for (int k = 0; k <= 4; ++k)
    m.push_back(GiNaC::expand(w1 + (1 - w1) * (alpha * ipow(c, k) + (1 - alpha) * ipow(t, k))));
  return m;
}

// ---------------------------------------------------------------------------------------------
// Part D: one certified cap.

struct CapCase {
  std::string name;
  numeric c_low, c_high;  // the cap is z >= c with c_low <= c <= c_high (equal when c is rational)
  ex c_exact;             // c itself (rational or sqrt(3)/2)
  numeric t_start;        // a rough t (the brief's double-precision value) to start Newton from
};

struct Certified {
  numeric lower, upper, eps, t_hat, alpha_hat;
};

}  // namespace

int main() {
  const symbol x("x"), y("y"), z("z");
  // =============================================================================================
  std::cout << "Part A: rotation-invariant measures\n";
  // Step 1: rotations about z act on h by a matrix of determinant 1.
  {
    const symbol co("co"), si("si");
    const ex X = co * x - si * y, Y = si * x + co * y;
    const matrix hR = sym::design_row({X, Y, z});
    const matrix h = sym::design_row({x, y, z});
    const std::vector<ex> mon{x, y, z, x * x, y * y, z * z, x * y, y * z, z * x};
    matrix TR(9, 9);
    bool linear = true;
    for (int i = 0; i < 9; ++i) {
      const ex e = GiNaC::expand(hR(i, 0));
      ex rest = e;
      for (int j = 0; j < 9; ++j) {
        const int dx = mon[static_cast<std::size_t>(j)].degree(x), dy = mon[static_cast<std::size_t>(j)].degree(y),
                  dz = mon[static_cast<std::size_t>(j)].degree(z);
        TR(i, j) = e.coeff(x, dx).coeff(y, dy).coeff(z, dz);
        rest -= TR(i, j) * mon[static_cast<std::size_t>(j)];
      }
      linear = linear && GiNaC::expand(rest).is_zero();
    }
    const ex det =
        GiNaC::expand(TR.determinant()).subs(GiNaC::pow(si, 2) == 1 - co * co, GiNaC::subs_options::algebraic);
    check(
        linear && GiNaC::expand(det - 1).is_zero(),
        "step 1: h(R x) = T_R h(x) for the rotation R about z by any angle (co, si), det T_R = 1 when co^2 + si^2 = 1");
  }
  // Step 2: the mean over a circle, and the moment matrix of a rotation-invariant measure.
  {
    bool wallis = true, hexagon = true;
    auto dfact = [](int n) {
      numeric r = 1;
      for (int k = n; k > 1; k -= 2) r *= k;
      return r;
    };
    const ex s3 = GiNaC::sqrt(ex(3)) / 2;
    const ex co6[6] = {1, ex(1) / 2, -ex(1) / 2, -1, -ex(1) / 2, ex(1) / 2};
    const ex si6[6] = {0, s3, s3, 0, -s3, -s3};
    for (int a = 0; a <= 4; ++a)
      for (int b = 0; a + b <= 4; ++b) {
        const ex want = (a % 2 || b % 2) ? ex(0) : ex(dfact(a - 1) * dfact(b - 1) / dfact(a + b));
        wallis = wallis && zero(circle_mean(a, b) - want);
        ex six = 0;
        for (int k = 0; k < 6; ++k) six += ipow(co6[k], a) * ipow(si6[k], b);
        hexagon = hexagon && zero(six / 6 - want);
      }
    check(wallis,
          "step 2: mean of cos^a sin^b over a turn (constant Fourier term) = (a-1)!!(b-1)!!/(a+b)!! (a, b even), else "
          "0; a+b <= 4");
    check(hexagon, "remark: 6 equally spaced points on a circle have the circle's means of cos^a sin^b, a+b <= 4");
  }
  const symbol m0("m0"), m1("m1"), m2("m2"), m3("m3"), m4("m4");
  const std::vector<ex> m{m0, m1, m2, m3, m4};
  const matrix h = sym::design_row({x, y, z});
  auto moment_matrix = [&](const std::vector<ex>& mm) {
    matrix M(9, 9);
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) M(i, j) = expect(ring_mean(h(i, 0) * h(j, 0), x, y, z), z, mm);
    return M;
  };
  const matrix Mh = moment_matrix(m);
  // u = T h: (1, z, z^2 | x, xz | y, yz | x^2 - y^2, 2xy), slot 0 being x^2 + y^2 + z^2 = 1.
  matrix T(9, 9);
  T(0, 3) = 1, T(0, 4) = 1, T(0, 5) = 1;  // x^2 + y^2 + z^2
  T(1, 2) = 1;                            // z
  T(2, 5) = 1;                            // z^2
  T(3, 0) = 1;                            // x
  T(4, 8) = 1;                            // zx
  T(5, 1) = 1;                            // y
  T(6, 7) = 1;                            // yz
  T(7, 3) = 1, T(7, 4) = -1;              // x^2 - y^2
  T(8, 6) = 2;                            // 2xy
  const matrix u = T.mul(h);
  const ex sphere = x * x + y * y + z * z;
  const matrix u_want(9, 1, GiNaC::lst{sphere, z, z * z, x, x * z, y, y * z, x * x - y * y, 2 * x * y});
  bool u_ok = true;
  for (int i = 0; i < 9; ++i) u_ok = u_ok && GiNaC::expand(u(i, 0) - u_want(i, 0)).is_zero();
  const ex detT = T.determinant();
  std::cout << "  det T = " << detT << "\n";
  check(u_ok && GiNaC::expand(detT * detT - 16).is_zero(),
        "step 2: T h = (x^2+y^2+z^2, z, z^2, x, xz, y, yz, x^2-y^2, 2xy) (= u on the sphere), det T^2 = 16");
  const Blocks G = blocks_of(m);
  const matrix Mu = T.mul(Mh).mul(T.transpose());
  {
    matrix want(9, 9);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) want(i, j) = G.H(i, j);
    for (int k : {3, 5})
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) want(k + i, k + j) = G.B(i, j) / 2;
    want(7, 7) = G.q / 2, want(8, 8) = G.q / 2;
    bool ok = true;
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) ok = ok && GiNaC::expand(Mu(i, j) - want(i, j)).is_zero();
    check(ok,
          "step 2: T M_h T^T = diag(H, B/2, B/2, q/2, q/2) for symbolic moments m0..m4 (every entry of M_h from the "
          "circle means)");
    const ex detMh = GiNaC::expand(Mh.determinant());
    const ex want_det = GiNaC::expand(G.H.determinant() * GiNaC::pow(G.B.determinant(), 2) * G.q * G.q / 64);
    check(GiNaC::expand(detMh * 16 - want_det).is_zero(),
          "step 2: det M_h = det H det(B)^2 q^2 / (64 det T^2) = det H det(B)^2 q^2 / 1024 (9x9 determinant, symbolic "
          "moments)");
  }
  // Step 3: the sensitivity, identically in the inverses (any symmetric Hi, Bi and qi).
  {
    const symbol k00("k00"), k01("k01"), k02("k02"), k11("k11"), k12("k12"), k22("k22"), b00("b00"), b01("b01"),
        b11("b11"), qi("qi");
    const matrix Hi(3, 3, GiNaC::lst{k00, k01, k02, k01, k11, k12, k02, k12, k22});
    const matrix Bi(2, 2, GiNaC::lst{b00, b01, b01, b11});
    matrix Ki(9, 9);  // the inverse of diag(H, B/2, B/2, q/2, q/2)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Ki(i, j) = Hi(i, j);
    for (int k : {3, 5})
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) Ki(k + i, k + j) = 2 * Bi(i, j);
    Ki(7, 7) = 2 * qi, Ki(8, 8) = 2 * qi;
    const ex d_u = u.transpose().mul(Ki).mul(u)(0, 0);
    const ex diff = GiNaC::expand(GiNaC::expand(d_u - sensitivity(Hi, Bi, qi, z))
                                      .subs(GiNaC::pow(x, 2) == 1 - y * y - z * z, GiNaC::subs_options::algebraic));
    check(diff.is_zero(),
          "step 3: h^T M_h^-1 h = u^T M_u^-1 u = v^T H^-1 v + 2(1-z^2) w^T B^-1 w + 2(1-z^2)^2/q on the sphere");
    check(GiNaC::expand(sensitivity(Hi, Bi, qi, z)).degree(z) == 4,
          "step 3: d is a polynomial in z of degree <= 4 (here 4)");
  }

  // =============================================================================================
  std::cout << "Part B: three rings, pole weight, stationarity\n";
  const symbol w1("w1"), al("alpha"), c("c"), t("t");
  const ex rc = 1 - c * c, rt = 1 - t * t;
  const ex Q = al * rc * rc + (1 - al) * rt * rt;
  const ex V = (c - 1) * (t - 1) * (t - c);
  {
    const Blocks G3 = blocks_of(three_ring_moments(w1, al, c, t));
    check(GiNaC::expand(G3.H.determinant() - w1 * GiNaC::pow(1 - w1, 2) * al * (1 - al) * V * V).is_zero(),
          "step 5: det H = w1 (1-w1)^2 alpha (1-alpha) V^2, V = (c-1)(t-1)(t-c)");
    check(GiNaC::expand(G3.B.determinant() - GiNaC::pow(1 - w1, 2) * al * (1 - al) * rc * rt * GiNaC::pow(t - c, 2))
              .is_zero(),
          "step 5: det B = (1-w1)^2 alpha (1-alpha) r(c) r(t) (t-c)^2, r(z) = 1 - z^2");
    check(GiNaC::expand(G3.q - (1 - w1) * Q).is_zero(), "step 5: q = (1-w1) Q, Q = alpha r(c)^2 + (1-alpha) r(t)^2");
  }
  const ex prod = GiNaC::pow(al * (1 - al), 3) * Q * Q * GiNaC::pow(1 + c, 2) * GiNaC::pow(1 - c, 4) *
                  GiNaC::pow(1 + t, 2) * GiNaC::pow(1 - t, 4) * GiNaC::pow(t - c, 6);
  check(
      GiNaC::expand(GiNaC::pow(al * (1 - al), 3) * V * V * GiNaC::pow(rc * rt, 2) * GiNaC::pow(t - c, 4) * Q * Q - prod)
          .is_zero(),
      "step 5: (alpha(1-alpha))^3 V^2 (r(c) r(t))^2 (t-c)^4 Q^2 = (alpha(1-alpha))^3 Q^2 (1+c)^2 (1-c)^4 (1+t)^2 "
      "(1-t)^4 (t-c)^6");
  {
    const ex f = GiNaC::log(w1) + 8 * GiNaC::log(1 - w1);
    check(zero(f.diff(w1).subs(w1 == ex(1) / 9)) && zero(f.diff(w1, 2) + 1 / (w1 * w1) + 8 / GiNaC::pow(1 - w1, 2)),
          "step 5: w1 (1-w1)^8 is maximised on (0,1) at w1 = 1/9 only (log strictly concave, derivative 0 there)");
  }
  const ex Phi = 3 * GiNaC::log(al * (1 - al)) + 2 * GiNaC::log(Q) + 2 * GiNaC::log(1 + c) + 4 * GiNaC::log(1 - c) +
                 2 * GiNaC::log(1 + t) + 4 * GiNaC::log(1 - t) + 6 * GiNaC::log(t - c);
  const ex Dl = rc * rc - rt * rt;
  const ex E1 = GiNaC::expand(-8 * Dl * al * al + (5 * Dl - 6 * rt * rt) * al + 3 * rt * rt);
  const ex Qt = -4 * t * (1 - al) * rt;
  const ex E2 = GiNaC::expand(Qt * rt * (t - c) + Q * ((1 - t) * (t - c) - 2 * (1 + t) * (t - c) + 3 * rt));
  check(zero(Phi.diff(al) * al * (1 - al) * Q - E1),
        "step 5: dPhi/dalpha * alpha(1-alpha) Q = E1 = -8 Delta alpha^2 + (5 Delta - 6 r(t)^2) alpha + 3 r(t)^2, Delta "
        "= r(c)^2 - r(t)^2");
  check(
      zero(Phi.diff(t) * Q * rt * (t - c) / 2 - E2),
      "step 5: dPhi/dt * Q (1-t^2)(t-c)/2 = E2 = -4t(1-alpha)(1-t^2)^2(t-c) + Q ((1-t)(t-c) - 2(1+t)(t-c) + 3(1-t^2))");
  check(GiNaC::expand(E1.subs(al == 0) - 3 * rt * rt).is_zero() &&
            GiNaC::expand(E1.subs(al == 1) + 3 * rc * rc).is_zero(),
        "step 5: E1(alpha=0) = 3 r(t)^2 > 0, E1(alpha=1) = -3 r(c)^2 < 0: one root alpha in (0,1) for every c < t < 1");
  const ex Dform = GiNaC::pow(ex(9), 9) / (GiNaC::pow(ex(2), 14) * prod);
  {
    const std::vector<ex> mm = three_ring_moments(ex(1) / 9, al, c, t);
    const Blocks G3 = blocks_of(mm);
    const ex detMu = G3.H.determinant() * GiNaC::pow(G3.B.determinant(), 2) * G3.q * G3.q / 64;
    check(zero(16 / detMu - Dform),
          "step 5: D(alpha, t; c) = det T^2 / det M_u = 9^9 / (2^14 (alpha(1-alpha))^3 Q^2 (1+c)^2 (1-c)^4 (1+t)^2 "
          "(1-t)^4 (t-c)^6)");
  }
  // The resultant and its factors.
  const ex P = GiNaC::expand(-39 * GiNaC::pow(c, 4) * t * t - 16 * GiNaC::pow(c, 4) * t - GiNaC::pow(c, 4) +
                             48 * GiNaC::pow(c, 3) * GiNaC::pow(t, 3) + 6 * GiNaC::pow(c, 3) * t * t -
                             48 * GiNaC::pow(c, 3) * t - 6 * GiNaC::pow(c, 3) + 39 * c * c * GiNaC::pow(t, 4) +
                             6 * c * c * GiNaC::pow(t, 3) + 48 * c * c * t * t + 26 * c * c * t - 7 * c * c +
                             30 * c * GiNaC::pow(t, 5) + 6 * c * GiNaC::pow(t, 4) - 108 * c * GiNaC::pow(t, 3) -
                             18 * c * t * t + 78 * c * t + 12 * c + 10 * GiNaC::pow(t, 5) - 29 * GiNaC::pow(t, 4) -
                             26 * GiNaC::pow(t, 3) - 29 * t * t + 18);
  {
    const ex R = GiNaC::expand(GiNaC::resultant(E1, E2, al));
    const ex trivial = GiNaC::pow(c - 1, 2) * GiNaC::pow(c + 1, 2) * GiNaC::pow(t - 1, 2) * GiNaC::pow(t - c, 2) *
                       GiNaC::pow(t + 1, 2);
    const ex k = GiNaC::normal(R / (trivial * P));
    std::cout << "  R(c,t) = Res_alpha(E1, E2): degree " << R.degree(t) << " in t, " << R.degree(c) << " in c, "
              << R.nops() << " terms\n";
    std::cout << "  factored: " << sym::canonical_text(GiNaC::factor(R)) << "\n";
    check(is_rational(k) && GiNaC::expand(R - k * trivial * P).is_zero(),
          "step 5: R = Res_alpha(E1, E2) = 2 (c-1)^2 (c+1)^2 (t-1)^2 (t-c)^2 (t+1)^2 P(c,t)");
    std::cout << "  constant " << k << "\n";
    const ex fP = GiNaC::factor(P);
    check(P.degree(t) == 5 && P.degree(c) == 4 && !GiNaC::is_a<GiNaC::mul>(fP) && !GiNaC::is_a<GiNaC::power>(fP),
          "step 5: P has degree 5 in t, 4 in c (total 6) and is irreducible over Q (GiNaC factor)");
    std::cout << "  P(c,t) = " << sym::canonical_text(P) << "\n";
  }
  // One root of P(c, .) in (c, 1) for every c in (-1, 1).
  {
    check(GiNaC::expand(P.subs(t == c) - 6 * GiNaC::pow(c - 1, 2) * GiNaC::pow(c + 1, 2) * (13 * c * c + 2 * c + 3))
                  .is_zero() &&
              real_roots(13 * c * c + 2 * c + 3, c) == 0 && num((13 * c * c + 2 * c + 3).subs(c == 0)).is_positive(),
          "step 5: P(c,c) = 6 (c-1)^2 (c+1)^2 (13c^2+2c+3) > 0 on (-1,1) (13c^2+2c+3 has no real root)");
    check(GiNaC::expand(P.subs(t == 1) + 56 * GiNaC::pow(c - 1, 2) * GiNaC::pow(c + 1, 2)).is_zero(),
          "step 5: P(c,1) = -56 (c-1)^2 (c+1)^2 < 0 on (-1,1)");
    const ex Rd = GiNaC::expand(GiNaC::resultant(P, P.diff(t), t));
    const ex known = (3 * c + 1) * GiNaC::pow(c + 3, 2) * GiNaC::pow(c - 1, 4) * GiNaC::pow(c + 1, 4);
    const ex rest = GiNaC::normal(Rd / known);
    const ex restq = GiNaC::expand(rest);
    bool poly = GiNaC::expand(rest * known - Rd).is_zero() && restq.is_polynomial(c);
    std::cout << "  Res_t(P, dP/dt): degree " << Rd.degree(c)
              << " in c, factored: " << sym::canonical_text(GiNaC::factor(Rd)) << "\n";
    check(poly && restq.degree(c) == 16 && real_roots(restq, c) == 0,
          "step 5: Res_t(P, dP/dt) = (3c+1)(c+3)^2(c-1)^4(c+1)^4 f(c), f of degree 16 (times a constant) with no real "
          "root (Sturm)");
    const ex Pm = GiNaC::expand(P.subs(c == -ex(1) / 3));
    check(Pm.degree(t) == 4 && !GiNaC::expand(GiNaC::resultant(Pm, Pm.diff(t), t)).is_zero(),
          "step 5: at c = -1/3 (leading coefficient 10(3c+1) = 0) P(-1/3, t) has degree 4 and no multiple root");
    check(roots_between(P.subs(c == 0), t, 0, 1) == 1, "step 5: P(0, t) has exactly one root in (0, 1) (Sturm)");
  }

  // =============================================================================================
  std::cout << "Part C: the threshold c* = -(1+sqrt 6)/5\n";
  const ex cs = -(1 + GiNaC::sqrt(ex(6))) / 5, ts = (GiNaC::sqrt(ex(6)) - 1) / 5;
  {
    std::vector<ex> mu;  // z-moments of the uniform sphere: z uniform on [-1, 1] (Archimedes)
    for (int k = 0; k <= 4; ++k) mu.push_back(GiNaC::integral(z, -1, 1, GiNaC::pow(z, k) / 2).eval_integ());
    check(mu[0].is_equal(1) && mu[1].is_equal(0) && mu[2].is_equal(ex(1) / 3) && mu[3].is_equal(0) &&
              mu[4].is_equal(ex(1) / 5),
          "step 6: the uniform sphere has (m0..m4) = (1, 0, 1/3, 0, 1/5)");
    const matrix Mun = moment_matrix(mu);
    const matrix Msym = sym::symmetric_moment_matrix(ex(1) / 15);
    bool same = true;
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) same = same && zero(Mun(i, j) - Msym(i, j));
    check(same,
          "step 6: a rotation-invariant measure with these z-moments has the uniform moment matrix of Theorem 2 (b = "
          "1/15)");
    const Blocks Gu = blocks_of(mu);
    check(num(Gu.H(0, 0)).is_positive() && num(Gu.H(0, 0) * Gu.H(1, 1) - Gu.H(0, 1) * Gu.H(1, 0)).is_positive() &&
              GiNaC::expand(Gu.H.determinant() - ex(4) / 135).is_zero(),
          "step 6: the Hankel matrix of (1, 0, 1/3, 0, 1/5) is positive definite (leading minors 1, 1/3, 4/135)");
    matrix L(2, 2);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) L(i, j) = expect((z - c) * (1 - z) * GiNaC::pow(z, i + j), z, mu);
    check(GiNaC::expand(L(0, 0) - (-ex(1) / 3 - c)).is_zero() && GiNaC::expand(L(0, 1) - (1 + c) / 3).is_zero() &&
              GiNaC::expand(L(1, 1) - (-ex(1) / 5 - c / 3)).is_zero(),
          "step 6: localising matrix E[(z-c)(1-z)(1,z)^T(1,z)] = [[-1/3-c, (1+c)/3], [(1+c)/3, -1/5-c/3]]");
    check(GiNaC::expand(L.determinant() - ex(2) / 45 * (5 * c * c + 2 * c - 1)).is_zero(),
          "step 6: its determinant is (2/45)(5c^2 + 2c - 1)");
    const ex other = (GiNaC::sqrt(ex(6)) - 1) / 5;  // the other root
    check(zero((5 * c * c + 2 * c - 1).subs(c == cs)) && zero((5 * c * c + 2 * c - 1).subs(c == other)) &&
              sign_in(cs + ex(1) / 3, 6) < 0 && sign_in(other + ex(1) / 3, 6) > 0,
          "step 6: 5c^2+2c-1 = 5 (c - c*)(c - (sqrt6-1)/5) and c* < -1/3 < (sqrt6-1)/5: PSD iff c <= c*");
    const ex k0 = L(0, 0) - L(0, 1) / ts, k1 = L(1, 0) - L(1, 1) / ts;
    check(zero(k0.subs(c == cs)) && zero(k1.subs(c == cs)),
          "step 6: L(c*) (1, -1/t*)^T = 0: E[(z-c*)(1-z)(1-z/t*)^2] = 0, so a solution at c* lives on {c*, t*, 1}");
    // The exact measure at c*: atoms c*, t*, 1 with the uniform moments.
    const matrix Vm(3, 3, GiNaC::lst{1, 1, 1, cs, ts, 1, cs * cs, ts * ts, 1});
    const matrix rhs(3, 1, GiNaC::lst{1, 0, ex(1) / 3});
    const matrix W = Vm.inverse().mul(rhs);
    const ex wr = sym::canonical(W(0, 0)), wt = sym::canonical(W(1, 0)), wp = sym::canonical(W(2, 0));
    bool moments_ok = true;
    for (int k = 0; k <= 4; ++k)
      moments_ok =
          moments_ok && zero(wr * GiNaC::pow(cs, k) + wt * GiNaC::pow(ts, k) + wp - mu[static_cast<std::size_t>(k)]);
    std::cout << "  c* = " << sym::canonical_text(cs) << ", t* = " << sym::canonical_text(ts) << "\n";
    std::cout << "  weights: rim " << sym::canonical_text(wr) << ", circle " << sym::canonical_text(wt) << ", pole "
              << sym::canonical_text(wp) << "\n";
    check(moments_ok && zero(wr - (16 - GiNaC::sqrt(ex(6))) / 36) && zero(wt - (16 + GiNaC::sqrt(ex(6))) / 36) &&
              zero(wp - ex(1) / 9),
          "step 6: on {c*, t*, 1}, t* = (sqrt6-1)/5, the weights ((16-sqrt6)/36, (16+sqrt6)/36, 1/9) give moments (1, "
          "0, 1/3, 0, 1/5)");
    check(sign_in(wr, 6) > 0 && sign_in(wt, 6) > 0 && sign_in(ts - cs, 6) > 0 && sign_in(1 - ts, 6) > 0 &&
              sign_in(cs + 1, 6) > 0,
          "step 6: the weights are positive and -1 < c* < t* < 1 (exact signs in Q(sqrt 6))");
    const ex as = wr * 9 / 8;
    check(zero(as - (ex(1) / 2 - GiNaC::sqrt(ex(6)) / 32)),
          "step 6: its alpha* = 1/2 - sqrt6/32 (pole weight exactly 1/9)");
    const GiNaC::exmap at{{al, as}, {t, ts}, {c, cs}};
    check(zero(E1.subs(at)) && zero(E2.subs(at)) && zero(P.subs(at)),
          "step 6: (alpha*, t*) solves E1 = E2 = 0 at c = c*, and P(c*, t*) = 0: the end of the family t(c)");
    check(zero(Dform.subs(at) - ex(61509375) / 4), "step 6: D(alpha*, t*; c*) = 61509375/4, the sphere's limit");
    std::cout << "  theta* = arccos(c*) = " << GiNaC::evalf(GiNaC::acos(cs) * 180 / GiNaC::Pi)
              << " degrees (numerically)\n";
  }

  // =============================================================================================
  std::cout << "Part D: certified limits by weak duality\n";
  const numeric s3low = GiNaC::isqrt(numeric(3) * pow10(100)) / (2 * pow10(50));
  const std::vector<CapCase> cases{
      {"c = sqrt(3)/2 (30 deg)", s3low, s3low + pow10(-50), GiNaC::sqrt(ex(3)) / 2, numeric(94337341, 100000000)},
      {"c = 1/2 (60 deg)", numeric(1, 2), numeric(1, 2), ex(1) / 2, numeric(79153064, 100000000)},
      {"c = 0 (90 deg, hemisphere)", 0, 0, 0, numeric(58703203, 100000000)},
      {"c = -1/2 (120 deg)", numeric(-1, 2), numeric(-1, 2), -ex(1) / 2, numeric(36902257, 100000000)},
  };
  check(s3low.is_positive() && s3low * s3low < numeric(3, 4) &&
            (s3low + pow10(-50)) * (s3low + pow10(-50)) > numeric(3, 4),
        "step 7: c_low < sqrt(3)/2 < c_high = c_low + 10^-50 (exact squares)");
  const numeric sphere_limit = numeric(61509375, 4);
  for (const auto& cc : cases) {
    std::cout << "  " << cc.name << "\n";
    // Newton in exact rationals on E1 = E2 = 0 at c = c_high (iterates rounded to 80 digits).
    const ex e1 = E1.subs(c == cc.c_high), e2 = E2.subs(c == cc.c_high);
    const ex j11 = e1.diff(al), j12 = e1.diff(t), j21 = e2.diff(al), j22 = e2.diff(t);
    numeric tn = cc.t_start, an;
    {  // alpha from E1 at the start t by bisection (E1 > 0 at 0, < 0 at 1)
      numeric lo = 0, hi = 1;
      for (int i = 0; i < 30; ++i) {
        const numeric mid = (lo + hi) / 2;
        (num(e1.subs(GiNaC::exmap{{al, mid}, {t, tn}})).is_positive() ? lo : hi) = mid;
      }
      an = (lo + hi) / 2;
    }
    numeric step = 1;
    int iterations = 0;
    for (; iterations < 30 && GiNaC::abs(step) > pow10(-75); ++iterations) {
      const GiNaC::exmap at{{al, an}, {t, tn}};
      const numeric f1 = num(e1.subs(at)), f2 = num(e2.subs(at));
      const numeric a11 = num(j11.subs(at)), a12 = num(j12.subs(at)), a21 = num(j21.subs(at)), a22 = num(j22.subs(at));
      const numeric det = a11 * a22 - a12 * a21;
      const numeric da = (a22 * f1 - a12 * f2) / det, dt = (a11 * f2 - a21 * f1) / det;
      an = round_to(an - da, 80);
      tn = round_to(tn - dt, 80);
      step = GiNaC::abs(da) + GiNaC::abs(dt);
    }
    const numeric ah = round_to(an, 45), th = round_to(tn, 45);
    // The measure xi^: pole 1/9, rim (8/9) alpha^ at c_high (inside the cap), circle (8/9)(1 - alpha^) at t^.
    const std::vector<ex> mh = three_ring_moments(ex(1) / 9, ah, cc.c_high, th);
    const Blocks Gh = blocks_of(mh);
    const numeric detH = num(Gh.H.determinant()), detB = num(Gh.B.determinant()), qh = num(Gh.q);
    const numeric Dhat = numeric(1024) / (detH * detB * detB * qh * qh);
    const ex dhat = GiNaC::expand(sensitivity(Gh.H.inverse(), Gh.B.inverse(), 1 / Gh.q, z));
    bool rational_quartic = dhat.degree(z) == 4;
    for (int k = 0; k <= 4; ++k) rational_quartic = rational_quartic && is_rational(dhat.coeff(z, k));
    // A first guess of sup d^ (not a proof): d^ at c_low, 1 and its critical point near t^.
    numeric zc = th;
    const ex dd = dhat.diff(z), ddd = dd.diff(z);
    for (int i = 0; i < 8; ++i) zc = round_to(zc - num(dd.subs(z == zc)) / num(ddd.subs(z == zc)), 90);
    numeric guess = std::max({num(dhat.subs(z == cc.c_low)), num(dhat.subs(z == 1)), num(dhat.subs(z == zc))});
    numeric excess = guess / 9 - 1;
    if (!excess.is_positive()) excess = pow10(-60);
    // eps: twice the guessed excess, rounded up to one significant digit; raised tenfold until proven.
    int ex10 = 0;
    while (excess * 2 < pow10(ex10 - 1)) --ex10;
    numeric eps = ceil_q(excess * 2 / pow10(ex10 - 1)) * pow10(ex10 - 1);
    bool proven = false;
    for (int tries = 0; tries < 6 && !proven; ++tries, eps *= 10) {
      const ex g = GiNaC::expand(9 * (1 + eps) - dhat);
      proven = num(g.subs(z == cc.c_low)).is_positive() && num(g.subs(z == 1)).is_positive() &&
               roots_between(g, z, cc.c_low, 1) == 0;
      if (proven) break;
    }
    const numeric lower = Dhat / (1 + eps).power(9);
    const numeric width = 1 - numeric(1) / (1 + eps).power(9);
    // t(c): the unique root of P(c, .) in (c, 1) lies within 10^-44 of t^ (P changes sign there).
    const ex Pc = P.subs(c == cc.c_exact);
    const int s_lo = sign_in(Pc.subs(t == th - pow10(-44)), 3), s_hi = sign_in(Pc.subs(t == th + pow10(-44)), 3);
    std::cout << "    Newton: " << iterations << " steps; t^ = " << fixed(th, 45) << ", alpha^ = " << fixed(ah, 45)
              << "\n";
    std::cout << "    weights (rim, circle, pole) = (" << fixed(ah * 8 / 9, 30) << ", " << fixed((1 - ah) * 8 / 9, 30)
              << ", 1/9)\n";
    const numeric kappa = num(dhat.coeff(z, 4));
    const ex shape = GiNaC::expand(dhat - 9 - kappa * (z - cc.c_high) * (z - 1) * GiNaC::pow(z - th, 2));
    numeric off = 0;
    for (int k = 0; k <= 4; ++k) off = std::max(off, GiNaC::abs(num(shape.coeff(z, k))));
    std::cout << "    d^ - 9 = kappa (z-c)(z-1)(z-t^)^2 up to coefficients below 1e-38, kappa = "
              << sci(kappa, 12, false) << "\n";
    std::cout << "    sup d^ <= 9 (1 + eps), eps = " << sci(eps, 1, true) << "\n";
    std::cout << "    D limit in [" << sci(lower, 36, false) << ", " << sci(Dhat, 36, true) << "]\n";
    std::cout << "    relative width < " << sci(width, 2, true) << "; limit / sphere's limit ~ "
              << sci(Dhat / sphere_limit, 12, false) << "\n";
    const std::string n = cc.name;
    check(ah.is_positive() && ah < 1 && th > cc.c_high && th < 1,
          (n + ": xi^ (pole 1/9, rim (8/9) alpha^ at c_high >= c, circle (8/9)(1-alpha^) at t^) lies in the cap")
              .c_str());
    check(rational_quartic, (n + ": d^(z) of the rational measure xi^ is an exact rational quartic").c_str());
    check(off < pow10(-38) && kappa.is_positive(),
          (n + ": d^ - 9 - kappa (z-c)(z-1)(z-t^)^2 has coefficients below 1e-38, kappa > 0 (the shape of step 5)")
              .c_str());
    check(proven, (n + ": 9(1+eps) - d^(z) > 0 on [c_low, 1] (endpoint values and no root: Sturm, exact)").c_str());
    check(width < pow10(-30) && lower > sphere_limit,
          (n + ": the enclosure [D(xi^)(1+eps)^-9, D(xi^)] has relative width < 1e-30 and lies above 61509375/4")
              .c_str());
    check(s_lo > 0 && s_hi < 0, (n + ": P(c, t^ - 1e-44) > 0 > P(c, t^ + 1e-44): |t(c) - t^| < 1e-44").c_str());
  }
  return scalcal::proofs::finish();
}
