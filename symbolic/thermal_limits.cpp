// The interval's exact optimal values (thermal_limits.hpp).
#include "symbolic/thermal_limits.hpp"

#include <algorithm>
#include <vector>

namespace scalcal::symbolic {
namespace {

// Coefficients c_0..c_n of P_k' made monic (c_0 = 1, the leading one), highest power first.
std::vector<GiNaC::ex> monic_legendre_derivative(int k) {
  const GiNaC::symbol t("t");
  GiNaC::ex p0 = 1, p1 = t;
  for (int n = 2; n <= k; ++n) {
    const GiNaC::ex p2 = GiNaC::expand(((2 * n - 1) * t * p1 - (n - 1) * p0) / n);
    p0 = p1;
    p1 = p2;
  }
  const GiNaC::ex d = GiNaC::expand(k == 1 ? GiNaC::ex(1) : p1.diff(t));
  const int n = d.degree(t);
  std::vector<GiNaC::ex> c;
  for (int i = n; i >= 0; --i) c.push_back(d.coeff(t, i) / d.coeff(t, n));
  return c;
}

// 1 / det of the Hankel matrix of the moments of equal weights on -1, 1 and the roots of P_k'.
GiNaC::ex d_factor(int k) {
  const std::vector<GiNaC::ex> c = monic_legendre_derivative(k);
  const int n = static_cast<int>(c.size()) - 1;                      // k - 1 roots
  std::vector<GiNaC::ex> p(static_cast<std::size_t>(2 * k + 1), 0);  // power sums p_m of the roots
  p[0] = n;
  for (int m = 1; m <= 2 * k; ++m) {
    GiNaC::ex s = m <= n ? GiNaC::ex(m) * c[static_cast<std::size_t>(m)] : GiNaC::ex(0);
    for (int i = 1; i <= std::min(m - 1, n); ++i)
      s += c[static_cast<std::size_t>(i)] * p[static_cast<std::size_t>(m - i)];
    p[static_cast<std::size_t>(m)] = GiNaC::expand(-s);
  }
  GiNaC::matrix M(static_cast<unsigned>(k + 1), static_cast<unsigned>(k + 1));
  for (int i = 0; i <= k; ++i)
    for (int j = 0; j <= k; ++j) {
      const int m = i + j;
      const GiNaC::ex ends = m % 2 == 0 ? 2 : 0;  // (-1)^m + 1^m
      M(static_cast<unsigned>(i), static_cast<unsigned>(j)) = (ends + p[static_cast<std::size_t>(m)]) / (k + 1);
    }
  return GiNaC::normal(1 / M.determinant());
}

}  // namespace

GiNaC::ex interval_factor_exact(CriterionKind c, int k) {
  if (c == CriterionKind::D && k >= 1 && k <= 6) return d_factor(k);
  if (k == 1 && (c == CriterionKind::A)) return 2;
  if (k == 1 && (c == CriterionKind::E || c == CriterionKind::S)) return 1;
  if (k == 2 && c == CriterionKind::A) return 8;
  if (k == 2 && c == CriterionKind::E) return 5;
  if (k == 2 && c == CriterionKind::S) return 4;
  if (k == 3 && c == CriterionKind::E) return 25;
  if (k == 3 && c == CriterionKind::S) return 16;
  return 0;
}

}  // namespace scalcal::symbolic
