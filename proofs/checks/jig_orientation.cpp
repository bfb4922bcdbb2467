// Theorem 6 (jigs): the information matrix of the dodecahedral and icosahedral jigs does not
// depend on the meter's orientation. With R(q) from a symbolic quaternion q (R~ = |q|^2 R has
// polynomial entries), sum_i m(R~ eta_i) = |q|^(2 deg m) sum_i m(eta_i) for every monomial m of
// degree 2, 3, 4: these sums are exactly the entries of H^T H.
#include "proofs/checks/check.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/jigs.hpp"

using GiNaC::ex;
using GiNaC::symbol;
using scalcal::proofs::check;
namespace sym = scalcal::symbolic;

namespace {
// x^0 = 1 even for x = 0 (GiNaC leaves 0^0 undefined).
ex ipow(const ex& x, int e) { return e == 0 ? ex(1) : GiNaC::pow(x, e); }

bool invariant(const std::vector<sym::WeightedPoint>& pts, const GiNaC::matrix& R, const ex& n) {
  for (int deg = 2; deg <= 4; ++deg)
    for (int i = 0; i <= deg; ++i)
      for (int j = 0; i + j <= deg; ++j) {
        const int k = deg - i - j;
        ex rotated = 0, plain = 0;
        for (const auto& p : pts) {
          ex v[3];
          for (int r = 0; r < 3; ++r) v[r] = R(r, 0) * p.eta[0] + R(r, 1) * p.eta[1] + R(r, 2) * p.eta[2];
          rotated += ipow(v[0], i) * ipow(v[1], j) * ipow(v[2], k);
          plain += ipow(p.eta[0], i) * ipow(p.eta[1], j) * ipow(p.eta[2], k);
        }
        if (!sym::is_zero_exact(GiNaC::expand(rotated) - GiNaC::pow(n, deg) * sym::canonical(plain))) return false;
      }
  return true;
}
}  // namespace

int main() {
  const symbol a("a"), b("b"), c("c"), d("d");
  const ex n = a * a + b * b + c * c + d * d;
  const GiNaC::matrix R(3, 3,
                        GiNaC::lst{a * a + b * b - c * c - d * d, 2 * (b * c - a * d), 2 * (b * d + a * c),
                                   2 * (b * c + a * d), a * a - b * b + c * c - d * d, 2 * (c * d - a * b),
                                   2 * (b * d - a * c), 2 * (c * d + a * b), a * a - b * b - c * c + d * d});
  const GiNaC::matrix RRt = R.mul(R.transpose());
  bool orth = true;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) orth = orth && GiNaC::expand(RRt(i, j) - (i == j ? n * n : ex(0))).is_zero();
  check(orth && GiNaC::expand(R.determinant() - GiNaC::pow(n, 3)).is_zero(),
        "R(q) = R~/|q|^2 is a rotation for every q != 0");
  check(invariant(sym::dodecahedral_points(), R, n), "dodecahedral jig: H^T H unchanged by every rotation R(q)");
  check(invariant(sym::icosahedral_points(), R, n), "icosahedral jig: H^T H unchanged by every rotation R(q)");
  // Control: the six axis positions (a 3-design, not a 4-design) must fail the same test.
  std::vector<sym::WeightedPoint> axes;
  for (int i = 0; i < 3; ++i)
    for (int sgn : {1, -1}) {
      sym::Point p{0, 0, 0};
      p[i] = sgn;
      axes.push_back({1, p});
    }
  check(!invariant(axes, R, n), "control: the six axis positions are not rotation invariant");
  return scalcal::proofs::finish();
}
