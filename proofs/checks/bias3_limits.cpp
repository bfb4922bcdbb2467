// Bias3 limits: h = (x, y, z), P = 3. Written with GiNaC symbols only (independent of
// numeric/model): tr M = E[h^T h] = 1 for every measure; the eigenvalue inequalities behind
// D = 27, A = 9, E = 3, S = 3 and their equality cases; the equivalence-theorem certificates
// (constant on the sphere); and the tight-frame programs eta_k = (sqrt(2/3) cos t_k,
// sqrt(2/3) sin t_k, 1/sqrt3), t_k = 2 pi k/N, with sum eta eta^T = (N/3) I for N = 3..40.
#include <iostream>
#include <string>

#include <ginac/ginac.h>

#include "proofs/checks/check.hpp"
#include "proofs/checks/sphere_reduction.hpp"
#include "symbolic/exact.hpp"

using GiNaC::ex;
using GiNaC::matrix;
using GiNaC::symbol;
using scalcal::proofs::check;
using scalcal::proofs::on_sphere;
using scalcal::proofs::quad;
using scalcal::proofs::scaled_identity;
using scalcal::symbolic::canonical;
using scalcal::symbolic::is_zero_exact;

int main() {
  const symbol x("x"), y("y"), z("z");
  const matrix h(3, 1, GiNaC::lst{x, y, z});

  // tr M = E[h^T h] and h^T h = 1 on the sphere.
  check(on_sphere(quad(h, scaled_identity(3, 1)) - 1, x, y, z).is_zero(),
        "h^T h = x^2 + y^2 + z^2 = 1 on the sphere: tr M = 1 for every measure");

  // Eigenvalue inequalities (mu_i > 0 the eigenvalues of M, sum mu = 1).
  const symbol m1("mu1"), m2("mu2"), m3("mu3");
  const ex cs =
      (m1 + m2 + m3) * (1 / m1 + 1 / m2 + 1 / m3) - 9 -
      (GiNaC::pow(m1 - m2, 2) / (m1 * m2) + GiNaC::pow(m2 - m3, 2) / (m2 * m3) + GiNaC::pow(m3 - m1, 2) / (m3 * m1));
  check(GiNaC::normal(cs).is_zero(),
        "A: (sum mu)(sum 1/mu) - 9 = sum_{i<j} (mu_i - mu_j)^2/(mu_i mu_j) >= 0, so tr M^-1 >= 9, = iff all mu = 1/3");
  // AM-GM for three: with mu_i = t_i^3, t1^3 + t2^3 + t3^3 - 3 t1 t2 t3 = (t1+t2+t3) sum (t_i - t_j)^2 / 2.
  const symbol t1("t1"), t2("t2"), t3("t3");
  check(GiNaC::expand(GiNaC::pow(t1, 3) + GiNaC::pow(t2, 3) + GiNaC::pow(t3, 3) - 3 * t1 * t2 * t3 -
                      (t1 + t2 + t3) * (GiNaC::pow(t1 - t2, 2) + GiNaC::pow(t2 - t3, 2) + GiNaC::pow(t3 - t1, 2)) / 2)
            .is_zero(),
        "D: AM-GM (sum mu)/3 >= (mu1 mu2 mu3)^(1/3) via the SOS identity, so det M <= 1/27, = iff all mu = 1/3");
  // S: K_11 = 1/(M_11 - m^T S^-1 m) (Schur), so K_11 >= 1/M_11 with equality iff the off-diagonal row m = 0.
  {
    const symbol a("a"), p("p"), q("q"), s("s"), t("t"), r("r");
    const matrix M(3, 3, GiNaC::lst{a, p, q, p, s, t, q, t, r});
    const matrix S(2, 2, GiNaC::lst{s, t, t, r});
    const matrix m(2, 1, GiNaC::lst{p, q});
    const ex schur = a - m.transpose().mul(S.inverse()).mul(m)(0, 0);
    check(GiNaC::normal(M.inverse()(0, 0) * schur - 1).is_zero(),
          "S: (M^-1)_11 = 1/(M_11 - m^T S^-1 m) (Schur complement)");
  }

  // Certificates with M* = I/3, K = 3I: every sensitivity is constant on the sphere.
  const matrix K = scaled_identity(3, 3);
  check(on_sphere(quad(h, K) - 3, x, y, z).is_zero(), "D: h^T M*^-1 h = 3 = P on the sphere");
  check(on_sphere(quad(h, K.mul(K)) - 9, x, y, z).is_zero(), "A: h^T M*^-2 h = 9 = tr M*^-1 on the sphere");
  check(on_sphere(quad(h, scaled_identity(3, ex(1) / 3)) - ex(1) / 3, x, y, z).is_zero(),
        "E: Ehat = I/3 (trace 1), h^T Ehat h = 1/3 = lambda_min(M*) on the sphere");
  const matrix W = scaled_identity(3, ex(1) / 3);
  check(W.mul(K).trace().is_equal(3) && on_sphere(quad(h, K.mul(W).mul(K)) - 3, x, y, z).is_zero(),
        "S: W = I/3, h^T K W K h = 3 = tr(W K) on the sphere");

  // The tight frame: eta(t) eta(t)^T in terms of cos t, sin t, cos 2t, sin 2t.
  {
    const symbol tt("t");
    const ex c = GiNaC::cos(tt), s = GiNaC::sin(tt);
    // eta = e/sqrt3 with e = (sqrt2 cos t, sqrt2 sin t, 1): eta eta^T = e e^T / 3.
    const matrix e(3, 1, GiNaC::lst{GiNaC::sqrt(ex(2)) * c, GiNaC::sqrt(ex(2)) * s, 1});
    check(is_zero_exact(e.transpose().mul(e)(0, 0) - 3), "frame: |eta(t)|^2 = |e|^2/3 = 1");
    const ex c2 = 2 * c * c - 1, s2 = 2 * s * c;  // cos 2t, sin 2t
    const matrix want(
        3, 3,
        GiNaC::lst{(1 + c2) / 3, s2 / 3, GiNaC::sqrt(ex(2)) * c / 3, s2 / 3, (1 - c2) / 3, GiNaC::sqrt(ex(2)) * s / 3,
                   GiNaC::sqrt(ex(2)) * c / 3, GiNaC::sqrt(ex(2)) * s / 3, ex(1) / 3});
    const matrix got = e.mul(e.transpose()).mul_scalar(ex(1) / 3);
    bool ok = true;
    for (int r = 0; r < 3; ++r)
      for (int q = 0; q < 3; ++q) ok = ok && is_zero_exact(got(r, q) - want(r, q));
    check(ok, "frame: eta eta^T = I/3 + (1/3)[[cos2t, sin2t, sqrt2 cos t], [sin2t, -cos2t, sqrt2 sin t], [., ., 0]]");
  }
  {
    // sum_k eta_k eta_k^T = (N/3) I, numerically with 60 digits (the exact statement is the
    // roots-of-unity argument: sum_k w^{mk} = 0 for w = e^{2 pi i/N}, m = 1, 2 < N).
    GiNaC::Digits = 60;
    bool ok = true;
    GiNaC::numeric worst = 0;
    const GiNaC::numeric tol = GiNaC::ex_to<GiNaC::numeric>(GiNaC::pow(ex(10), -30));
    for (int N = 3; N <= 40; ++N) {
      matrix S(3, 3);
      for (int kk = 0; kk < N; ++kk) {
        const ex t = 2 * GiNaC::Pi * kk / N;
        const ex c = GiNaC::evalf(GiNaC::cos(t)), s = GiNaC::evalf(GiNaC::sin(t));
        const ex k = GiNaC::evalf(GiNaC::sqrt(ex(2) / 3));
        const matrix e(3, 1, GiNaC::lst{k * c, k * s, GiNaC::evalf(1 / GiNaC::sqrt(ex(3)))});
        S = S.add(e.mul(e.transpose()));
      }
      for (int r = 0; r < 3; ++r)
        for (int q = 0; q < 3; ++q) {
          const GiNaC::numeric d =
              GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(S(r, q) - (r == q ? ex(N) / 3 : ex(0)))));
          if (d > worst) worst = d;
          if (d > tol) ok = false;
        }
    }
    std::cout << "  max |sum eta eta^T - (N/3) I| over N = 3..40: " << worst << "\n";
    check(ok, "frame: sum_k eta_k eta_k^T = (N/3) I to 1e-30 for N = 3..40");
  }
  return scalcal::proofs::finish();
}
