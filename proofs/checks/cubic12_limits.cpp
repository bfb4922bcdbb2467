// Cubic12 limits: h = (x, y, z, x^2, y^2, z^2, xy, yz, zx, x^3, y^3, z^3), P = 12. Written with
// GiNaC symbols only (independent of numeric/model): the 48-fold symmetry and the block form of
// a symmetric moment matrix; the chord bound p6 <= 1/9 + (4/3)(p4 - 1/3) that reduces the
// symmetric problem to the family "lambda on the 6 axes, 1 - lambda on the 8 cube diagonals";
// the exact D, A, E, S optima on that family; the equivalence-theorem certificates
// bound - h^T Q h = beta (e2 - 9 e3) on the sphere (so the limits hold over ALL measures and every
// optimal measure lives on the 14 points); and which N-point programs attain each limit.
#include <algorithm>
#include <array>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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
using scalcal::symbolic::canonical;
using scalcal::symbolic::is_zero_exact;

namespace {
constexpr int P = 12;
using Pt = std::array<ex, 3>;

matrix design_row(const Pt& e) {
  const ex &x = e[0], &y = e[1], &z = e[2];
  return matrix(P, 1, GiNaC::lst{x, y, z, x * x, y * y, z * z, x * y, y * z, z * x, x * x * x, y * y * y, z * z * z});
}

bool is_zero_matrix(const matrix& m) {
  for (unsigned r = 0; r < m.rows(); ++r)
    for (unsigned c = 0; c < m.cols(); ++c)
      if (!is_zero_exact(m(r, c))) return false;
  return true;
}

matrix canon(const matrix& m) {
  matrix out(m.rows(), m.cols());
  for (unsigned r = 0; r < m.rows(); ++r)
    for (unsigned c = 0; c < m.cols(); ++c) out(r, c) = canonical(m(r, c));
  return out;
}

// sum_k w_k h(eta_k) h(eta_k)^T, entries canonical.
matrix moments(const std::vector<ex>& w, const std::vector<Pt>& pts) {
  matrix M(P, P);
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const matrix h = design_row(pts[k]);
    M = M.add(h.mul(h.transpose()).mul_scalar(w[k]));
  }
  return canon(M);
}

// The 14 points: +-e_x, +-e_y, +-e_z, then (s_x, s_y, s_z)/sqrt 3.
std::vector<Pt> fourteen() {
  std::vector<Pt> pts;
  for (int i = 0; i < 3; ++i)
    for (int s : {1, -1}) {
      Pt p{0, 0, 0};
      p[i] = s;
      pts.push_back(p);
    }
  const ex r = 1 / GiNaC::sqrt(ex(3));
  for (int sx : {1, -1})
    for (int sy : {1, -1})
      for (int sz : {1, -1}) pts.push_back(Pt{sx * r, sy * r, sz * r});
  return pts;
}

std::vector<ex> family_weights(const ex& axis_point, const ex& cube_point) {
  std::vector<ex> w(6, axis_point);
  w.insert(w.end(), 8, cube_point);
  return w;
}

// The moment matrix of a G-invariant measure: bias/cubic pairs [[1/3, a4], [a4, a6]] per axis,
// squares (a4 - b) I + b J, nonorth b I.
matrix symmetric_model(const ex& a4, const ex& a6, const ex& b) {
  matrix M(P, P);
  for (int i = 0; i < 3; ++i) {
    M(i, i) = ex(1) / 3;
    M(i, 9 + i) = M(9 + i, i) = a4;
    M(9 + i, 9 + i) = a6;
    for (int j = 0; j < 3; ++j) M(3 + i, 3 + j) = i == j ? a4 : b;
    M(6 + i, 6 + i) = b;
  }
  return M;
}

// Exact rank by Gaussian elimination, zero tests by canonical().
int exact_rank(matrix A) {
  const unsigned m = A.rows(), n = A.cols();
  unsigned rank = 0;
  for (unsigned c = 0; c < n && rank < m; ++c) {
    unsigned piv = m;
    for (unsigned r = rank; r < m; ++r)
      if (!is_zero_exact(A(r, c))) {
        piv = r;
        break;
      }
    if (piv == m) continue;
    for (unsigned k = 0; k < n; ++k) std::swap(A(rank, k), A(piv, k));
    for (unsigned r = rank + 1; r < m; ++r) {
      if (is_zero_exact(A(r, c))) continue;
      const ex f = A(r, c) / A(rank, c);
      for (unsigned k = c; k < n; ++k) A(r, k) = canonical(A(r, k) - f * A(rank, k));
    }
    ++rank;
  }
  return static_cast<int>(rank);
}

bool divides(long d, long n) { return n % d == 0; }

matrix at(const matrix& m, const GiNaC::exmap& sub) { return canon(GiNaC::ex_to<matrix>(m.subs(sub))); }
matrix at(const matrix& m, const ex& sym, const ex& value) { return at(m, GiNaC::exmap{{sym, value}}); }

std::string text(const ex& e) {
  std::ostringstream s;
  s << e;
  return s.str();
}
}  // namespace

int main() {
  const symbol x("x"), y("y"), z("z"), lam("lambda");
  const Pt eta{x, y, z};
  const matrix h = design_row(eta);
  const ex u1 = x * x, u2 = y * y, u3 = z * z;
  const ex p4 = u1 * u1 + u2 * u2 + u3 * u3, p6 = u1 * u1 * u1 + u2 * u2 * u2 + u3 * u3 * u3;
  const ex e2 = u1 * u2 + u2 * u3 + u3 * u1, e3 = u1 * u2 * u3;

  // ---- 1. Symmetry: h(g eta) = T_g h(eta), and the G-average of h h^T on the sphere.
  std::array<int, 3> perm{0, 1, 2};
  matrix avg(P, P);
  int count = 0;
  bool signed_perm = true, equivariant = true;
  do {
    for (int s = 0; s < 8; ++s) {
      Pt g;
      for (int i = 0; i < 3; ++i) g[i] = ((s >> i) & 1 ? -1 : 1) * eta[perm[i]];
      const matrix hg = design_row(g);
      matrix T(P, P);
      for (int r = 0; r < P; ++r) {
        int hits = 0;
        for (int c = 0; c < P; ++c)
          for (int sign : {1, -1})
            if (GiNaC::expand(hg(r, 0) - sign * h(c, 0)).is_zero()) T(r, c) = sign, ++hits;
        if (hits != 1) signed_perm = false;
      }
      const matrix TTt = T.mul(T.transpose());
      for (int r = 0; r < P; ++r)
        for (int c = 0; c < P; ++c)
          if (!(TTt(r, c) - (r == c ? 1 : 0)).is_zero()) signed_perm = false;
      const matrix Th = T.mul(h);
      for (int r = 0; r < P; ++r)
        if (!GiNaC::expand(Th(r, 0) - hg(r, 0)).is_zero()) equivariant = false;
      avg = avg.add(hg.mul(hg.transpose()));
      ++count;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  check(count == 48 && signed_perm,
        "each of the 48 signed permutations g acts on h by a signed permutation matrix T_g");
  check(equivariant, "h(g eta) = T_g h(eta) as polynomial identities");
  {
    const ex a4 = p4 / 3, a6 = p6 / 3;
    const matrix model = symmetric_model(a4, a6, (ex(1) / 3 - a4) / 2);
    bool ok = true;
    for (int r = 0; r < P; ++r)
      for (int c = 0; c < P; ++c)
        if (!on_sphere(avg(r, c) / 48 - model(r, c), x, y, z).is_zero()) ok = false;
    check(ok,
          "G-average of h h^T = blocks [[1/3,a4],[a4,a6]] x3, (a4-b)I+bJ, bI with a4=p4/3, a6=p6/3, b=(1/3-a4)/2 on "
          "the sphere");
    const symbol A4("a4"), A6("a6"), B("b");
    const matrix dM = GiNaC::ex_to<matrix>(symmetric_model(A4, A6, B).diff(A6));
    bool loewner = true;
    for (int r = 0; r < P; ++r)
      for (int c = 0; c < P; ++c)
        if (!(dM(r, c) - (r == c && r >= 9 ? 1 : 0)).is_zero()) loewner = false;
    check(loewner, "dM/da6 = diag(0,...,0,1,1,1) >= 0: M increases (Loewner) with a6 at fixed a4");
  }

  // ---- 2. The chord p6 <= 1/9 + (4/3)(p4 - 1/3) on the simplex.
  {
    const symbol v1("u1"), v2("u2"), v3("u3");
    const ex E1 = v1 + v2 + v3, E2 = v1 * v2 + v2 * v3 + v3 * v1, E3 = v1 * v2 * v3;
    const ex P4 = v1 * v1 + v2 * v2 + v3 * v3, P6 = GiNaC::pow(v1, 3) + GiNaC::pow(v2, 3) + GiNaC::pow(v3, 3);
    const ex chord = P6 - ex(1) / 9 - ex(4) / 3 * (P4 - ex(1) / 3) + (E2 - 9 * E3) / 3;
    check(GiNaC::expand(chord.subs(v3 == 1 - v1 - v2)).is_zero(),
          "p6 - 1/9 - (4/3)(p4 - 1/3) = -(e2 - 9 e3)/3 when u1 + u2 + u3 = 1");
    const ex sos = v1 * GiNaC::pow(v2 - v3, 2) + v2 * GiNaC::pow(v3 - v1, 2) + v3 * GiNaC::pow(v1 - v2, 2);
    check(GiNaC::expand(E1 * E2 - 9 * E3 - sos).is_zero(),
          "e1 e2 - 9 e3 = u1(u2-u3)^2 + u2(u3-u1)^2 + u3(u1-u2)^2 >= 0 (AM-GM)");
    bool zeros = true;
    for (const auto& p : fourteen()) {
      const GiNaC::exmap at{{x, p[0]}, {y, p[1]}, {z, p[2]}};
      if (!is_zero_exact((e2 - 9 * e3).subs(at))) zeros = false;
    }
    check(zeros, "e2 - 9 e3 = 0 at the 6 axis points and the 8 cube diagonals");
  }

  // ---- 3. The family xi_lambda: lambda/6 on each axis point, (1 - lambda)/8 on each cube point.
  const std::vector<Pt> pts = fourteen();
  const matrix M = moments(family_weights(lam / 6, (1 - lam) / 8), pts);
  const ex a4 = (1 + 2 * lam) / 9, a6 = (1 + 8 * lam) / 27, b = (1 - lam) / 9;
  check(is_zero_matrix(M.sub(symmetric_model(a4, a6, b))),
        "M(xi_lambda) = symmetric form with a4 = (1+2l)/9, a6 = (1+8l)/27, b = (1-l)/9");
  check(
      is_zero_exact(3 * a6 - (ex(1) / 9 + ex(4) / 3 * (3 * a4 - ex(1) / 3))) && is_zero_exact(b - (ex(1) / 3 - a4) / 2),
      "xi_lambda lies on the chord (3 a6 = 1/9 + (4/3)(3 a4 - 1/3)) and b = (1/3 - a4)/2");
  const matrix Bl(2, 2, GiNaC::lst{ex(1) / 3, a4, a4, a6});
  check(is_zero_exact(Bl.determinant() - 4 * lam * (1 - lam) / 81) && is_zero_exact(a4 - b - lam / 3),
        "det B = 4 l (1 - l)/81, a4 - b = l/3");
  check(is_zero_exact(M.determinant() - 64 * GiNaC::pow(lam, 5) * GiNaC::pow(1 - lam, 6) / GiNaC::pow(ex(3), 21)),
        "det M(lambda) = 64 l^5 (1-l)^6 / 3^21");
  const matrix K = canon(M.inverse());
  {
    const ex bias = 3 * (1 + 8 * lam) / (4 * lam * (1 - lam)), scale = (2 + lam) / lam, nonorth = 9 / (1 - lam),
             cubic = 27 / (4 * lam * (1 - lam));
    bool ok = true;
    for (int i = 0; i < 3; ++i)
      ok = ok && is_zero_exact(K(i, i) - bias) && is_zero_exact(K(3 + i, 3 + i) - scale) &&
           is_zero_exact(K(6 + i, 6 + i) - nonorth) && is_zero_exact(K(9 + i, 9 + i) - cubic);
    check(ok, "diag M^-1: bias 3(1+8l)/(4l(1-l)), scale (2+l)/l, nonorth 9/(1-l), cubic 27/(4l(1-l))");
    ex tr = 0;
    for (int i = 0; i < P; ++i) tr += K(i, i);
    check(is_zero_exact(tr - (3 + (57 + 78 * lam) / (2 * lam * (1 - lam)))), "tr M^-1 = 3 + (57 + 78 l)/(2 l (1 - l))");
  }

  // ---- 4. D: log det M = const + 5 log l + 6 log(1 - l).
  const ex lD = ex(5) / 11;
  check(is_zero_exact((5 / lam - 6 / (1 - lam)).subs(lam == lD)),
        "D: d/dl (5 log l + 6 log(1-l)) = 0 at l = 5/11 (max: strictly concave)");
  const ex Dval = canonical(1 / at(M, lam, lD).determinant());
  std::cout << "  D limit = " << Dval << " ~ " << GiNaC::evalf(Dval) << "\n";
  check(Dval.is_equal(GiNaC::numeric(4093910627611872177LL, 12800000)),
        "D limit = 4093910627611872177/12800000 ~ 3.19837e11");
  check(is_zero_exact(Dval -
                      GiNaC::pow(ex(3), 15) * GiNaC::pow(ex(11), 11) / (GiNaC::pow(ex(2), 12) * GiNaC::pow(ex(5), 5))),
        "D limit = 3^15 11^11 / (2^12 5^5) = 3^21 / (64 l^5 (1-l)^6) at l = 5/11");
  check((lD / 6).is_equal(ex(5) / 66) && ((1 - lD) / 8).is_equal(ex(3) / 44),
        "D: weights 5/66 per axis point, 3/44 per cube point");

  // ---- 5. A.
  const ex trK = 3 + (57 + 78 * lam) / (2 * lam * (1 - lam));
  {
    const ex dA = GiNaC::normal(trK.diff(lam));
    const ex ratio =
        GiNaC::normal(dA * 2 * GiNaC::pow(lam, 2) * GiNaC::pow(1 - lam, 2) / (26 * lam * lam + 38 * lam - 19));
    check(ratio.is_equal(3), "A: d/dl tr M^-1 = 3 (26 l^2 + 38 l - 19) / (2 l^2 (1-l)^2)");
  }
  const ex s95 = GiNaC::sqrt(ex(95));
  const ex lA = (3 * s95 - 19) / 26;
  check(is_zero_exact(26 * lA * lA + 38 * lA - 19), "A: l_A = (3 sqrt95 - 19)/26 is a root");
  const double lAd = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(lA)).to_double();
  const double lAo = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf((-3 * s95 - 19) / 26)).to_double();
  check(lAd > 0 && lAd < 1 && lAo < 0, "A: l_A ~ 0.39386 in (0,1), the other root (-3 sqrt95 - 19)/26 < 0");
  const ex Aval = canonical(trK.subs(lam == lA));
  std::cout << "  A limit = " << Aval << " ~ " << GiNaC::evalf(Aval) << "\n";
  check(is_zero_exact(Aval - (99 + 9 * s95)), "A limit = 99 + 9 sqrt 95 ~ 186.7211");
  check(is_zero_exact(canonical(trK.subs(lam == lA)) - canonical(at(K, lam, lA).trace())),
        "A: the closed form agrees with tr M(l_A)^-1");

  // ---- 6. E: lambda_min(B) at l = 11/26.
  const ex lE = ex(11) / 26;
  check(is_zero_exact(Bl.sub(matrix(2, 2, GiNaC::lst{ex(1) / 39, 0, 0, ex(1) / 39})).determinant() +
                      GiNaC::pow(26 * lam - 11, 2) / 13689),
        "E: det(B(l) - I/39) = -(26 l - 11)^2/13689 <= 0, so lambda_min(B) <= 1/39, = iff l = 11/26");
  {
    const matrix BE = at(Bl, lam, lE);
    const matrix v(2, 1, GiNaC::lst{2, -3});
    check(is_zero_matrix(BE.mul(v).sub(v.mul_scalar(ex(1) / 39))), "E: B(11/26) (2,-3) = (2,-3)/39");
    const matrix dB = GiNaC::ex_to<matrix>(Bl.diff(lam));
    check(is_zero_exact(v.transpose().mul(dB).mul(v)(0, 0)), "E: d lambda_min(B)/dl = v^T B' v / |v|^2 = 0 at 11/26");
    // A full eigenbasis of M(11/26): the minimum eigenvalue is 1/39.
    const matrix ME = at(M, lam, lE);
    std::vector<std::pair<matrix, ex>> basis;
    const ex mu2 = canonical(BE(0, 0) + BE(1, 1) - ex(1) / 39);
    for (int i = 0; i < 3; ++i) {
      matrix v1(P, 1), v2(P, 1), n1(P, 1);
      v1(i, 0) = 2, v1(9 + i, 0) = -3;
      v2(i, 0) = 3, v2(9 + i, 0) = 2;
      basis.push_back({v1, ex(1) / 39});
      basis.push_back({v2, mu2});
      n1(6 + i, 0) = 1;
      basis.push_back({n1, (1 - lE) / 9});
    }
    matrix sq1(P, 1), sq2(P, 1), sq3(P, 1);
    sq1(3, 0) = 1, sq1(4, 0) = -1;
    sq2(4, 0) = 1, sq2(5, 0) = -1;
    sq3(3, 0) = sq3(4, 0) = sq3(5, 0) = 1;
    basis.push_back({sq1, lE / 3});
    basis.push_back({sq2, lE / 3});
    basis.push_back({sq3, ex(1) / 3});
    bool eig = true;
    matrix V(P, P);
    ex smallest_other = 1;
    for (int k = 0; k < P; ++k) {
      eig = eig && is_zero_matrix(ME.mul(basis[k].first).sub(basis[k].first.mul_scalar(basis[k].second)));
      for (int r = 0; r < P; ++r) V(r, k) = basis[k].first(r, 0);
    }
    check(eig && !is_zero_exact(V.determinant()), "E: 12 independent eigenvectors of M(11/26)");
    bool others = true;
    for (int k = 0; k < P; ++k)
      if (!basis[k].second.is_equal(ex(1) / 39))
        others = others && GiNaC::ex_to<GiNaC::numeric>(canonical(basis[k].second - ex(1) / 39)).is_positive();
    check(others && mu2.is_equal(ex(55) / 117),
          "E: the other eigenvalues 55/117, 15/234, 11/78, 1/3 all exceed 1/39: lambda_min M(11/26) = 1/39, E limit = "
          "39");
  }

  // ---- 7. S: the cubic diagonal dominates and is minimal at l = 1/2.
  const ex lS = ex(1) / 2;
  check(is_zero_exact(27 / (4 * lam * (1 - lam)) - 3 * (1 + 8 * lam) / (4 * lam * (1 - lam)) - 6 / lam),
        "S: cubic - bias = 6/l > 0");
  check(is_zero_exact(27 / (4 * lam * (1 - lam)) - 27 - 27 * GiNaC::pow(1 - 2 * lam, 2) / (4 * lam * (1 - lam))),
        "S: 27/(4l(1-l)) - 27 = 27(1-2l)^2/(4l(1-l)) >= 0, = iff l = 1/2");
  {
    const matrix KS = at(K, lam, lS);
    check(KS(0, 0).is_equal(15) && KS(3, 3).is_equal(5) && KS(6, 6).is_equal(18) && KS(9, 9).is_equal(27),
          "S: at l = 1/2 diag M^-1 = (15, 5, 18, 27): max = 27, S limit = 27");
  }

  // ---- 8. Certificates (equivalence theorem): bound - h^T Q h = beta (e2 - 9 e3) on the sphere.
  const Pt half{1 / GiNaC::sqrt(ex(2)), 1 / GiNaC::sqrt(ex(2)), 0};  // e2 = 1/4, e3 = 0
  auto certify = [&](const std::string& name, const ex& bound, const matrix& Q, const ex& beta_expected) {
    const ex f = bound - quad(h, Q);
    const ex beta = canonical(4 * f.subs(GiNaC::exmap{{x, half[0]}, {y, half[1]}, {z, half[2]}}));
    std::cout << "  " << name << ": bound " << bound << ", beta = " << beta << "\n";
    check(is_zero_exact(on_sphere(f - beta * (e2 - 9 * e3), x, y, z)),
          (name + ": bound - h^T Q h = beta (e2 - 9 e3) identically on the sphere").c_str());
    check(is_zero_exact(beta - beta_expected), (name + ": beta = " + text(beta_expected) + " > 0").c_str());
  };
  {
    const matrix KD = at(K, lam, lD);
    certify("D", 12, KD, ex(363) / 40);
    check(is_zero_exact(KD.mul(at(M, lam, lD)).trace() - 12), "D: tr(M*^-1 M*) = 12 = P (bound)");
  }
  {
    const matrix K2 = canon(K.mul(K));
    matrix QA(P, P);
    for (int r = 0; r < P; ++r)
      for (int c = 0; c < P; ++c) QA(r, c) = canonical(K2(r, c).subs(lam == lA));
    // beta_A = 17199/95 + 351 sqrt95/19: both parts positive.
    certify("A", 99 + 9 * s95, QA, ex(17199) / 95 + 351 * s95 / 19);
  }
  {
    matrix Eh(P, P);
    for (int i = 0; i < 3; ++i) {
      Eh(i, i) = ex(4) / 39;
      Eh(i, 9 + i) = Eh(9 + i, i) = ex(-6) / 39;
      Eh(9 + i, 9 + i) = ex(9) / 39;
    }
    check(is_zero_exact(Eh.trace() - 1),
          "E: Ehat = (1/3) sum_axes v v^T, v = (2,-3)/sqrt13, is PSD (rank-1 blocks) with trace 1");
    check(is_zero_exact(Eh.mul(at(M, lam, lE)).trace() - ex(1) / 39), "E: tr(Ehat M*) = 1/39 = lambda_min(M*)");
    certify("E", ex(1) / 39, Eh, ex(1) / 13);
  }
  {
    const matrix KS = at(K, lam, lS);
    matrix W(P, P);
    for (int i = 9; i < 12; ++i) W(i, i) = ex(1) / 3;
    const matrix Q = KS.mul(W).mul(KS);
    check(is_zero_exact(W.mul(KS).trace() - 27), "S: W = 1/3 on the cubic rows, trace 1, tr(W M*^-1) = 27");
    check(is_zero_exact(on_sphere(quad(h, Q) - 27 * (u1 * GiNaC::pow(3 * u1 - 2, 2) + u2 * GiNaC::pow(3 * u2 - 2, 2) +
                                                     u3 * GiNaC::pow(3 * u3 - 2, 2)),
                                  x, y, z)),
          "S: h^T K W K h = 27 sum u (3u - 2)^2 on the sphere");
    certify("S", 27, Q, 81);
  }

  // ---- 9. Attainment.
  // (a) On the 14 points the weights are determined by M: the linear map w -> M(w) has rank 14.
  {
    matrix A(P * (P + 1) / 2, 14);
    int row = 0;
    std::vector<matrix> hs;
    for (const auto& p : pts) hs.push_back(design_row(p));
    for (int r = 0; r < P; ++r)
      for (int c = r; c < P; ++c, ++row)
        for (int k = 0; k < 14; ++k) A(row, k) = canonical(hs[k](r, 0) * hs[k](c, 0));
    check(exact_rank(A) == 14, "D, A: w -> sum_k w_k h_k h_k^T on the 14 points is injective (rank 14)");
    // The entries that carry the Walsh functions vanish on the axis points.
    const std::vector<std::pair<int, int>> walsh{{6, 6}, {0, 4}, {1, 5}, {2, 3}, {0, 1}, {1, 2}, {2, 0}, {0, 7}};
    matrix Wm(8, 8);
    bool axes_zero = true;
    for (int j = 0; j < 8; ++j) {
      for (int k = 0; k < 6; ++k)
        if (!is_zero_exact(hs[k](walsh[j].first, 0) * hs[k](walsh[j].second, 0))) axes_zero = false;
      for (int k = 0; k < 8; ++k) Wm(j, k) = canonical(hs[6 + k](walsh[j].first, 0) * hs[6 + k](walsh[j].second, 0));
    }
    check(axes_zero && exact_rank(Wm) == 8,
          "the entries xy.xy, x.y^2, y.z^2, z.x^2, x.y, y.z, z.x, x.yz vanish on the axes and carry the 8 Walsh "
          "functions (rank 8)");
  }
  {
    bool d132 = true, d624 = true, d48 = true;
    for (long N = 1; N <= 2000; ++N) {
      d132 = d132 && ((divides(66, 5 * N) && divides(44, 3 * N)) == divides(132, N));
      d624 = d624 && ((divides(156, 11 * N) && divides(208, 15 * N)) == divides(624, N));
      d48 = d48 && ((divides(12, N) && divides(16, N)) == divides(48, N));
    }
    check(d132, "D: N*5/66 and N*3/44 integers iff 132 | N (counts 10N/132 per axis, 9N/132 per cube point)");
    check(d624, "E: N*11/156 and N*15/208 integers iff 624 | N");
    check(d48, "S: N/12 and N/16 integers iff 48 | N");
  }
  // (b) E and S on the 14 points: the (x, x^3) principal block is W pp^T + C qq^T.
  const symbol Wx("W"), C("C");
  const matrix p(2, 1, GiNaC::lst{1, 1}),
      q(2, 1, GiNaC::lst{1 / GiNaC::sqrt(ex(3)), 1 / GiNaC::pow(GiNaC::sqrt(ex(3)), 3)});
  const matrix Bwc = canon(p.mul(p.transpose()).mul_scalar(Wx).add(q.mul(q.transpose()).mul_scalar(C)));
  {
    std::vector<symbol> ws;
    std::vector<ex> wex;
    for (int k = 0; k < 14; ++k) ws.emplace_back(std::string("w").append(std::to_string(k))), wex.push_back(ws.back());
    const matrix Mw = moments(wex, pts);
    ex Ctot = 0;
    for (int k = 6; k < 14; ++k) Ctot += ws[k];
    const matrix blk(2, 2, GiNaC::lst{Mw(0, 0), Mw(0, 9), Mw(9, 0), Mw(9, 9)});
    check(is_zero_matrix(blk.sub(at(Bwc, GiNaC::exmap{{Wx, ws[0] + ws[1]}, {C, Ctot}}))),
          "on the 14 points the (x, x^3) block is W_x [[1,1],[1,1]] + C [[1/3,1/9],[1/9,1/27]]");
    check(is_zero_matrix(at(Bwc, GiNaC::exmap{{Wx, lam / 3}, {C, 1 - lam}}).sub(Bl)),
          "with W = l/3, C = 1 - l the block is B(l)");
  }
  {
    const ex dE =
        canonical(at(Bwc, C, ex(15) / 26).sub(matrix(2, 2, GiNaC::lst{ex(1) / 39, 0, 0, ex(1) / 39})).determinant());
    check(is_zero_exact(dE - (dE.coeff(Wx, 1)) * (Wx - ex(11) / 78)) && !is_zero_exact(dE.coeff(Wx, 1)) &&
              dE.degree(Wx) == 1,
          "E: at C = 15/26, det(block - I/39) is linear in W with its only root W = 11/78");
    // Eigenvector equations M(w) vt_i = vt_i/39, vt_i = 2 e_i - 3 e_{9+i}: rank 14 in the weights.
    matrix A(36, 14);
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 14; ++k) {
        const matrix hk = design_row(pts[k]);
        const ex g = 2 * hk(i, 0) - 3 * hk(9 + i, 0);
        for (int r = 0; r < P; ++r) A(12 * i + r, k) = canonical(hk(r, 0) * g);
      }
    check(exact_rank(A) == 14, "E: the equations M(w) vt_i = vt_i/39 (i = x, y, z) determine the 14 weights (rank 14)");
    const matrix ME = moments(family_weights(ex(11) / 156, ex(15) / 208), pts);
    bool sol = true;
    for (int i = 0; i < 3; ++i) {
      matrix vt(P, 1);
      vt(i, 0) = 2, vt(9 + i, 0) = -3;
      sol = sol && is_zero_matrix(ME.mul(vt).sub(vt.mul_scalar(ex(1) / 39)));
    }
    check(sol && is_zero_matrix(ME.sub(at(M, lam, lE))),
          "E: the unique solution is 11/156 per axis point, 15/208 per cube point (= xi_{11/26})");
  }
  {
    const matrix Bs = Bwc;
    check(is_zero_exact(Bs(0, 0) / Bs.determinant() - (ex(27) / (4 * C) + ex(9) / (4 * Wx))),
          "S: 1/min_a E[(x^3 - a x)^2] = B11/det B = 27/(4C) + 9/(4W) on the 14 points");
    check(is_zero_exact(ex(27) / (4 * C) + ex(27) / (4 * (1 - C)) - 27 -
                        27 * GiNaC::pow(1 - 2 * C, 2) / (4 * C * (1 - C))),
          "S: 27/(4C) + 27/(4(1-C)) - 27 = 27(1-2C)^2/(4C(1-C)): C = 1/2 forced (then W_x = 1/6 by strict Jensen)");
    const matrix B6 = at(Bs, GiNaC::exmap{{Wx, ex(1) / 6}, {C, ex(1) / 2}});
    const ex alpha = canonical(B6(0, 1) / B6(0, 0));
    const matrix ut(2, 1, GiNaC::lst{-alpha, 1});
    check(alpha.is_equal(ex(2) / 3) && is_zero_exact(ut.transpose().mul(B6).mul(ut)(0, 0) - ex(1) / 27),
          "S: block minimiser u = x^3 - (2/3) x, E[u^2] = 1/27 = 1/K_rr");
    matrix A(36, 14);
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 14; ++k) {
        const matrix hk = design_row(pts[k]);
        const ex g = hk(9 + i, 0) - ex(2) / 3 * hk(i, 0);
        for (int r = 0; r < P; ++r) A(12 * i + r, k) = canonical(hk(r, 0) * g);
      }
    check(exact_rank(A) == 14, "S: the equations M(w) ut_i = e_{x_i^3}/27 determine the 14 weights (rank 14)");
    const matrix MS = moments(family_weights(ex(1) / 12, ex(1) / 16), pts);
    bool sol = true;
    for (int i = 0; i < 3; ++i) {
      matrix ut12(P, 1), e(P, 1);
      ut12(i, 0) = ex(-2) / 3, ut12(9 + i, 0) = 1, e(9 + i, 0) = ex(1) / 27;
      sol = sol && is_zero_matrix(MS.mul(ut12).sub(e));
    }
    check(sol && is_zero_matrix(MS.sub(at(M, lam, lS))),
          "S: the unique solution is 1/12 per axis point, 1/16 per cube point (= xi_{1/2})");
  }
  {
    bool none = true;
    for (long N = 1; N <= 40; ++N) none = none && !divides(132, N) && !divides(624, N) && !divides(48, N);
    check(none,
          "no program with N <= 40 attains D, E or S (132, 624, 48 do not divide N); A is never attained (l_A "
          "irrational)");
  }
  return scalcal::proofs::finish();
}
