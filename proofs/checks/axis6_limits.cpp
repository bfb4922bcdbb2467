// Axis6 limits: h = (x, y, z, x^2, y^2, z^2), P = 6. Written with GiNaC symbols only
// (independent of numeric/model): tr M = 1 + E[p4] <= 2 (2 - h^T h = 2 e2 on the sphere); the
// eigenvalue inequalities behind D = 729, A = 18, E = 3, S = 3; the moment matrix of any measure
// on the six axis points and the weights it forces; the equivalence-theorem certificates
// bound - h^T Q h = beta e2 on the sphere.
#include <iostream>
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
using scalcal::proofs::quad;
using scalcal::proofs::scaled_identity;
using scalcal::symbolic::canonical;
using scalcal::symbolic::is_zero_exact;

namespace {
constexpr int P = 6;
matrix design_row(const ex& x, const ex& y, const ex& z) {
  return matrix(P, 1, GiNaC::lst{x, y, z, x * x, y * y, z * z});
}
}  // namespace

int main() {
  const symbol x("x"), y("y"), z("z");
  const matrix h = design_row(x, y, z);
  const ex u1 = x * x, u2 = y * y, u3 = z * z;
  const ex p4 = u1 * u1 + u2 * u2 + u3 * u3, e2 = u1 * u2 + u2 * u3 + u3 * u1;

  check(on_sphere(quad(h, scaled_identity(P, 1)) - (1 + p4), x, y, z).is_zero(),
        "h^T h = 1 + p4 on the sphere: tr M = 1 + E[p4]");
  check(on_sphere(2 - quad(h, scaled_identity(P, 1)) - 2 * e2, x, y, z).is_zero(),
        "2 - h^T h = 2 e2 >= 0 on the sphere: tr M <= 2, = iff the measure lives where e2 = 0 (the six axis points)");

  // Eigenvalue inequalities for six positive eigenvalues.
  {
    std::vector<symbol> mu;
    for (int i = 0; i < P; ++i) mu.emplace_back(std::string("mu").append(std::to_string(i)));
    ex sum = 0, inv = 0, sos = 0;
    for (int i = 0; i < P; ++i) sum += mu[i], inv += 1 / mu[i];
    for (int i = 0; i < P; ++i)
      for (int j = i + 1; j < P; ++j) sos += GiNaC::pow(mu[i] - mu[j], 2) / (mu[i] * mu[j]);
    check(GiNaC::normal(sum * inv - 36 - sos).is_zero(),
          "A: (sum mu)(sum 1/mu) - 36 = sum_{i<j} (mu_i - mu_j)^2/(mu_i mu_j): tr M^-1 >= 36/tr M >= 18");
  }

  // Any measure on the six axis points: M is the direct sum of [[W, d], [d, W]] on (x_i, x_i^2).
  {
    std::vector<symbol> w;
    for (int k = 0; k < 6; ++k) w.emplace_back(std::string("w").append(std::to_string(k)));
    matrix M(P, P);
    for (int i = 0; i < 3; ++i)
      for (int s : {1, -1}) {
        ex pt[3] = {0, 0, 0};
        pt[i] = s;
        const matrix hk = design_row(pt[0], pt[1], pt[2]);
        M = M.add(hk.mul(hk.transpose()).mul_scalar(w[2 * i + (s == 1 ? 0 : 1)]));
      }
    bool ok = true;
    for (int r = 0; r < P; ++r)
      for (int c = 0; c < P; ++c) {
        ex want = 0;
        const int ir = r % 3, ic = c % 3;
        if (ir == ic) want = (r == c) ? w[2 * ir] + w[2 * ir + 1] : w[2 * ir] - w[2 * ir + 1];
        ok = ok && GiNaC::expand(M(r, c) - want).is_zero();
      }
    check(ok, "on the axis points M = direct sum over i of [[W_i, d_i], [d_i, W_i]], W_i = w+ + w-, d_i = w+ - w-");
    const ex sol = GiNaC::lsolve(GiNaC::lst{w[0] + w[1] == ex(1) / 3, w[0] - w[1] == 0}, GiNaC::lst{w[0], w[1]});
    check(sol.op(0).rhs().is_equal(ex(1) / 6) && sol.op(1).rhs().is_equal(ex(1) / 6), "M = I/3 forces w+ = w- = 1/6");
    const symbol d("d");
    const matrix B(2, 2, GiNaC::lst{ex(1) / 3, d, d, ex(1) / 3});
    const ex Krr = GiNaC::normal(B.inverse()(0, 0));
    check(GiNaC::normal(Krr - 3 - 27 * d * d / (1 - 9 * d * d)).is_zero(),
          "S: K_rr of [[1/3, d], [d, 1/3]] = 3/(1 - 9 d^2) = 3 + 27 d^2/(1 - 9 d^2) >= 3, = iff d = 0");
  }

  // Certificates with M* = I/3 (K = 3I); each f = bound - h^T Q h equals beta e2 on the sphere.
  const matrix K = scaled_identity(P, 3);
  struct Cert {
    const char* name;
    ex bound;
    matrix Q;
    ex beta;
  };
  const matrix W = scaled_identity(P, ex(1) / 6);
  const std::vector<Cert> certs{
      {"D: 6 - h^T M*^-1 h = 6 e2 (bound P = 6)", 6, K, 6},
      {"A: 18 - h^T M*^-2 h = 18 e2 (bound tr M*^-1 = 18)", 18, K.mul(K), 18},
      {"E: 1/3 - h^T (I/6) h = e2/3 (Ehat = I/6, trace 1, bound lambda_min = 1/3)", ex(1) / 3, W, ex(1) / 3},
      {"S: 3 - h^T K W K h = 3 e2 (W = I/6, bound tr(W K) = 3)", 3, K.mul(W).mul(K), 3}};
  for (const auto& c : certs) check(on_sphere(c.bound - quad(h, c.Q) - c.beta * e2, x, y, z).is_zero(), c.name);
  check(W.mul(K).trace().is_equal(3) && K.trace().is_equal(18) && W.trace().is_equal(1),
        "the bounds: tr M*^-1 = 18, tr W = tr Ehat = 1, tr(W K) = 3");
  return scalcal::proofs::finish();
}
