// Gyros on a single-axis rate table (proofs/gyro_rate_table.md, Theorem 24), checked with GiNaC
// symbols only (independent of numeric/): the gradient of the gyro's modulus residual at X = 0 is
// h(eta) whatever the rate; a reversed turn is S h; per-segment rates scale the quadratic part; the
// symmetrised information is block diagonal; the Earth's rate over whole and partial turns and as a
// per-mounting bias; the g-sensitivity's gradient and the block structure of a mounting turned both
// ways; the icosahedron as six mountings turned both ways has the D limit's moment matrix.
#include <array>
#include <string>
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

namespace {

const symbol x("x"), y("y"), z("z");

struct Unknowns {
  std::array<symbol, 3> beta{symbol("beta_x"), symbol("beta_y"), symbol("beta_z")};
  std::array<symbol, 3> dk{symbol("dk_x"), symbol("dk_y"), symbol("dk_z")};
  std::array<symbol, 3> gamma{symbol("gamma_xy"), symbol("gamma_yz"), symbol("gamma_zx")};
  std::vector<symbol> all() const {
    return {beta[0], beta[1], beta[2], dk[0], dk[1], dk[2], gamma[0], gamma[1], gamma[2]};
  }
  ex at_zero(const ex& e) const {
    GiNaC::lst zero;
    for (const symbol& s : all()) zero.append(s == 0);
    return e.subs(zero);
  }
};

// (E + dK) Phi with phi_kj = phi_jk = gamma_kj / 2 and Phi's diagonal sqrt(1 - sum of its row's
// off-diagonal squares): the meter of numeric/calibration/meter_model.hpp, written out again.
matrix gain(const Unknowns& u) {
  matrix P(3, 3);
  const int pairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  for (int q = 0; q < 3; ++q) {
    P(pairs[q][0], pairs[q][1]) = u.gamma[q] / 2;
    P(pairs[q][1], pairs[q][0]) = u.gamma[q] / 2;
  }
  for (int k = 0; k < 3; ++k) {
    ex off = 0;
    for (int j = 0; j < 3; ++j)
      if (j != k) off += GiNaC::pow(P(k, j), 2);
    P(k, k) = GiNaC::sqrt(1 - off);
  }
  matrix D(3, 3);
  for (int k = 0; k < 3; ++k) D(k, k) = 1 + u.dk[k];
  return D.mul(P);
}

matrix column(const ex& a, const ex& b, const ex& c) { return matrix(3, 1, GiNaC::lst{a, b, c}); }
ex norm2(const matrix& v) { return v.transpose().mul(v)(0, 0); }

// h and its even part q.
std::vector<ex> h_row(const ex& a, const ex& b, const ex& c) {
  return {a, b, c, a * a, b * b, c * c, a * b, b * c, c * a};
}

bool all_zero_on_sphere(const std::vector<ex>& entries) {
  for (const ex& e : entries)
    if (!on_sphere(GiNaC::normal(e), x, y, z).is_zero()) return false;
  return true;
}

// Item 1: the gradient of |w| / omega at X = 0 with b = omega beta and Omega = omega eta.
void exactness() {
  const Unknowns u;
  const symbol omega("omega");
  const matrix eta = column(x, y, z);
  const matrix w =
      column(omega * u.beta[0], omega * u.beta[1], omega * u.beta[2]).add(gain(u).mul(eta).mul_scalar(omega));
  const ex f2 = norm2(w) / (omega * omega);  // (|w| / omega)^2; at X = 0 it is |eta|^2 = 1 on the sphere
  const std::vector<ex> h = h_row(x, y, z);
  std::vector<ex> diff;
  const auto vars = u.all();
  for (std::size_t r = 0; r < vars.size(); ++r) diff.push_back(u.at_zero(f2.diff(vars[r])) / 2 - h[r]);
  check(all_zero_on_sphere(diff),
        "1: d(|w|/omega)/dX at X = 0 is h(eta) on the sphere, for every omega (b = omega beta)");
  check(on_sphere(u.at_zero(f2) - 1, x, y, z).is_zero(), "1: at X = 0, |w|/omega = |eta| = 1");
}

// Item 2: h(-eta) = S h(eta); item 3's symmetrisation with the rate ratio r.
void reversal_and_rates() {
  const std::vector<ex> h = h_row(x, y, z), hm = h_row(-x, -y, -z);
  std::vector<ex> diff;
  for (int r = 0; r < 9; ++r)
    diff.push_back(hm[static_cast<std::size_t>(r)] - (r < 3 ? -1 : 1) * h[static_cast<std::size_t>(r)]);
  check(all_zero_on_sphere(diff), "2: h(-eta) = S h(eta), S = diag(-I3, I6)");

  // Rates: (|w_i| - omega_i) / omega0 with b = omega0 beta, Omega = omega_i eta.
  const Unknowns u;
  const symbol wi("omega_i"), w0("omega_0");
  const matrix eta = column(x, y, z);
  const matrix w = column(w0 * u.beta[0], w0 * u.beta[1], w0 * u.beta[2]).add(gain(u).mul(eta).mul_scalar(wi));
  const ex f2 = norm2(w);  // |w|^2; d|w| = d|w|^2 / (2 |w|), |w| = omega_i at X = 0 on the sphere
  std::vector<ex> rd;
  const auto vars = u.all();
  for (std::size_t r = 0; r < vars.size(); ++r) {
    const ex want = r < 3 ? h[r] : h[r] * wi / w0;
    rd.push_back(u.at_zero(f2.diff(vars[r])) / (2 * wi * w0) - want);
  }
  check(all_zero_on_sphere(rd), "3: d((|w_i| - omega_i)/omega_0)/dX at X = 0 is (eta, (omega_i/omega_0) q(eta))");

  // S h_r h_r^T S + h_r h_r^T = 2 diag(eta eta^T, r^2 q q^T).
  const symbol rr("r");
  matrix hr(9, 1);
  for (int k = 0; k < 9; ++k) hr(k, 0) = k < 3 ? h[static_cast<std::size_t>(k)] : rr * h[static_cast<std::size_t>(k)];
  matrix S(9, 9);
  for (int k = 0; k < 9; ++k) S(k, k) = k < 3 ? -1 : 1;
  const matrix outer = hr.mul(hr.transpose());
  const matrix sum = S.mul(outer).mul(S).add(outer);
  bool block = true;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) {
      const bool same = (i < 3) == (j < 3);
      const ex want = same ? 2 * outer(i, j) : ex(0);
      block = block && GiNaC::expand(sum(i, j) - want).is_zero();
    }
  check(block, "3: S h_r h_r^T S + h_r h_r^T = 2 diag(eta eta^T, r^2 q q^T): the symmetrised M is block diagonal");
}

// Item 4: the Earth's rate.
void earth_rate() {
  const symbol th("Theta"), ph("phi");
  // The perpendicular part turning with the table: its integral over [0, Theta].
  const ex s = GiNaC::sin(th), c = GiNaC::cos(th);
  check(GiNaC::expand(s.diff(th) - c).is_zero() && GiNaC::expand((1 - c).diff(th) - s).is_zero(),
        "4: (sin T, 1 - cos T) is the integral of (cos t, sin t) over [0, T]");
  // |(sin T, 1 - cos T)|^2 = 4 sin^2(T/2): with T = 2 phi and the double-angle formulas.
  const ex s2 = 2 * GiNaC::sin(ph) * GiNaC::cos(ph), c2 = 1 - 2 * GiNaC::pow(GiNaC::sin(ph), 2);
  const ex m2 = GiNaC::expand(s2 * s2 + (1 - c2) * (1 - c2) - 4 * GiNaC::pow(GiNaC::sin(ph), 2));
  check(GiNaC::expand(m2.subs(GiNaC::pow(GiNaC::cos(ph), 2) == 1 - GiNaC::pow(GiNaC::sin(ph), 2))).is_zero(),
        "4: |(sin T, 1 - cos T)| = 2|sin(T/2)|, zero for whole turns");
  // (tau omega + Omega_a) v = (omega + tau Omega_a) eta with eta = tau v, tau^2 = 1.
  const symbol tau("tau"), omega("omega"), oa("Omega_a");
  check(GiNaC::expand((tau * omega + oa) - tau * (omega + tau * oa)).subs(GiNaC::pow(tau, 2) == 1).is_zero(),
        "4: the whole-turn mean (tau omega + Omega_a) v is (omega + tau Omega_a) eta");
  // Unmodelled: h(eta)^T (eps v, 0, 0) = tau eps for eta = tau v, |v| = 1.
  const symbol eps("epsilon");
  const std::vector<ex> he = h_row(tau * x, tau * y, tau * z);
  const ex bias_term = he[0] * eps * x + he[1] * eps * y + he[2] * eps * z;
  check(on_sphere(GiNaC::expand(bias_term - tau * eps).subs(GiNaC::pow(tau, 2) == 1), x, y, z).is_zero(),
        "4: the term tau Omega_a/omega is h(eta)^T (Omega_a v/omega, 0, 0): a bias of the mounting");
  // A mounting turned both ways: H^T t over its pair is (2 eps v, 0).
  const std::vector<ex> hp = h_row(x, y, z), hm = h_row(-x, -y, -z);
  std::vector<ex> pair;
  for (int r = 0; r < 9; ++r) {
    const ex want = r < 3 ? 2 * eps * hp[static_cast<std::size_t>(r)] : ex(0);
    pair.push_back(hp[static_cast<std::size_t>(r)] * eps - hm[static_cast<std::size_t>(r)] * eps - want);
  }
  check(all_zero_on_sphere(pair), "4: turned both ways, the Earth's term reaches the bias columns only (2 eps v, 0)");
}

// Item 5: g-sensitivity, f = g v = g tau eta.
void g_sensitivity() {
  const Unknowns u;
  const symbol omega("omega"), g("g"), tau("tau");
  std::array<std::array<symbol, 3>, 3> Sg;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Sg[i][j] = symbol("S_" + std::to_string(i) + std::to_string(j));
  matrix Sm(3, 3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Sm(i, j) = Sg[i][j];
  const matrix eta = column(x, y, z);
  const matrix w = column(omega * u.beta[0], omega * u.beta[1], omega * u.beta[2])
                       .add(gain(u).mul(eta).mul_scalar(omega))
                       .add(Sm.mul(eta).mul_scalar(g * tau));
  const ex f2 = norm2(w) / (omega * omega);
  GiNaC::lst zero;
  for (const symbol& s : u.all()) zero.append(s == 0);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) zero.append(Sg[i][j] == 0);
  const ex e[3] = {x, y, z};
  std::vector<ex> diff;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) diff.push_back(f2.diff(Sg[i][j]).subs(zero) / 2 - g / omega * tau * e[i] * e[j]);
  check(all_zero_on_sphere(diff),
        "5: d(|w|/omega)/dS_g at 0 is (g/omega) tau eta eta^T: the row gains (g/omega) tau q(eta)");

  // A mounting turned both ways: rows (v, q, c q) and (-v, q, -c q).
  const symbol cc("c");
  const std::vector<ex> hv = h_row(x, y, z);
  matrix a(15, 1), b(15, 1);
  for (int k = 0; k < 9; ++k) {
    a(k, 0) = hv[static_cast<std::size_t>(k)];
    b(k, 0) = k < 3 ? -hv[static_cast<std::size_t>(k)] : hv[static_cast<std::size_t>(k)];
  }
  for (int k = 0; k < 6; ++k) {
    a(9 + k, 0) = cc * hv[static_cast<std::size_t>(3 + k)];
    b(9 + k, 0) = -cc * hv[static_cast<std::size_t>(3 + k)];
  }
  const matrix sum = a.mul(a.transpose()).add(b.mul(b.transpose()));
  auto group = [](int k) { return (k >= 3 && k < 9) ? 1 : 0; };  // 0: (beta, s), 1: (dk, gamma)
  bool split = true;
  for (int i = 0; i < 15; ++i)
    for (int j = 0; j < 15; ++j) {
      const ex want = group(i) == group(j) ? 2 * a(i, 0) * a(j, 0) : ex(0);
      split = split && GiNaC::expand(sum(i, j) - want).is_zero();
    }
  check(split, "5: turned both ways, M = 2 (v, c q)(v, c q)^T on (beta, s) + 2 q q^T on (dk, gamma), nothing across");
}

// Item 2's example: the icosahedron as six mountings turned both ways has the moment matrix of the
// D limit's optimal measure, 12 diag(I/3, (a - b) I + b J, b I) with a = E[x^4] = 1/5, b = 1/15.
void icosahedron() {
  const ex phi = (1 + GiNaC::sqrt(ex(5))) / 2, n = GiNaC::sqrt(1 + phi * phi);
  const std::vector<scalcal::symbolic::Point> mountings = {{ex(0), 1 / n, phi / n}, {ex(0), 1 / n, -phi / n},
                                                           {1 / n, phi / n, ex(0)}, {1 / n, -phi / n, ex(0)},
                                                           {phi / n, ex(0), 1 / n}, {-phi / n, ex(0), 1 / n}};
  std::vector<scalcal::symbolic::WeightedPoint> program;
  for (const auto& v : mountings) {
    program.push_back({ex(1), v});
    program.push_back({ex(1), {-v[0], -v[1], -v[2]}});
  }
  const matrix M = scalcal::symbolic::moment_matrix(program);
  const ex a = ex(1) / 5, b = ex(1) / 15;
  bool ok = true;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) {
      ex want = 0;
      if (i < 3 && i == j) want = ex(1) / 3;
      if (i >= 3 && i < 6 && j >= 3 && j < 6) want = i == j ? a : b;
      if (i >= 6 && i == j) want = b;
      ok = ok && scalcal::symbolic::is_zero_exact(M(i, j) - 12 * want);
    }
  check(ok,
        "2: six icosahedral mountings turned both ways: M = 12 diag(I/3, (1/5 - 1/15) I + J/15, I/15), D's optimal "
        "moments");
}

}  // namespace

int main() {
  exactness();
  reversal_and_rates();
  earth_rate();
  g_sensitivity();
  icosahedron();
  return scalcal::proofs::finish();
}
