// Exact one-dimensional minimisation of the symmetric-measure criteria. The pieces are rational
// in b, so candidate minimisers are roots of polynomial numerators; the limits in this model
// only need degree <= 2 (a higher degree throws, rather than guessing).
#include "symbolic/limits.hpp"

#include <limits>
#include <stdexcept>

#include "symbolic/criteria.hpp"
#include "symbolic/exact.hpp"

namespace scalcal::symbolic {

using GiNaC::ex;
using GiNaC::symbol;

GiNaC::matrix symmetric_moment_matrix(const ex& b) {
  const ex a = ex(1) / 3 - 2 * b;
  GiNaC::matrix M(9, 9);
  for (int i = 0; i < 3; ++i) {
    M(i, i) = ex(1) / 3;
    for (int j = 0; j < 3; ++j) M(3 + i, 3 + j) = i == j ? a : b;
    M(6 + i, 6 + i) = b;
  }
  return M;
}

std::vector<ex> criterion_pieces(CriterionKind c, const symbol& b) {
  // N = 1: the criteria of M/N are the normalised criteria.
  const ExactCriteria k = exact_criteria(symmetric_moment_matrix(b), 1);
  const ExactValue* v = k.of(c);
  return v ? v->candidates : std::vector<ex>{};
}

namespace {

// sqrt of a non-negative rational with square factors taken out (sqrt(648) -> 18 sqrt(2)).
ex sqrt_rational(const ex& r) {
  if (!GiNaC::is_a<GiNaC::numeric>(r) || !GiNaC::ex_to<GiNaC::numeric>(r).is_rational()) return GiNaC::sqrt(r);
  const GiNaC::numeric q = GiNaC::ex_to<GiNaC::numeric>(r);
  // sqrt(p/q) = sqrt(p q) / q, then split p q = s^2 t with t square-free.
  long n = (q.numer() * q.denom()).to_long(), out = 1;
  for (long f = 2; f * f <= n; ++f)
    while (n % (f * f) == 0) n /= f * f, out *= f;
  return ex(out) * GiNaC::sqrt(ex(n)) / ex(q.denom());
}

// Real roots of the numerator of a rational function of b (degree <= 2 after removing b^m).
std::vector<ex> numerator_roots(const ex& f, const symbol& b) {
  ex p = GiNaC::expand(GiNaC::normal(f).numer());
  if (p.is_zero()) return {};
  const int low = p.ldegree(b);
  p = GiNaC::expand(p / GiNaC::pow(b, low));
  const int deg = p.degree(b);
  if (deg == 0) return {};
  if (deg == 1) return {canonical(-p.coeff(b, 0) / p.coeff(b, 1))};
  if (deg > 2) throw std::runtime_error("minimise_max: a numerator of degree > 2");
  const ex A = p.coeff(b, 2), B = p.coeff(b, 1), C = p.coeff(b, 0);
  const ex disc = canonical(B * B - 4 * A * C);
  if (GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(disc)).to_double() < 0) return {};
  const ex root = sqrt_rational(disc);
  return {canonical((-B - root) / (2 * A)), canonical((-B + root) / (2 * A))};
}

double as_double(const ex& e) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(); }

}  // namespace

SymbolicLimit minimise_max(const std::vector<ex>& pieces, const symbol& b) {
  std::vector<ex> points;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    for (const auto& r : numerator_roots(GiNaC::diff(pieces[i], b), b)) points.push_back(r);
    for (std::size_t j = i + 1; j < pieces.size(); ++j)
      for (const auto& r : numerator_roots(pieces[i] - pieces[j], b)) points.push_back(r);
  }
  SymbolicLimit best{0, 0, 0};
  double best_v = std::numeric_limits<double>::infinity();
  for (const auto& p : points) {
    const double pv = as_double(p);
    if (!(pv > 0 && pv < 1.0 / 9)) continue;  // the open interval of non-singular symmetric measures
    ex top = 0;
    double top_v = -std::numeric_limits<double>::infinity();
    for (const auto& f : pieces) {
      const ex v = canonical(f.subs(b == p));
      if (as_double(v) > top_v) top_v = as_double(v), top = v;
    }
    if (top_v < best_v) best_v = top_v, best = {top, p, canonical(ex(1) / 3 - 2 * p)};
  }
  if (!(best_v < std::numeric_limits<double>::infinity()))
    throw std::runtime_error("minimise_max: no interior minimiser");
  return best;
}

bool has_symbolic_limit(CriterionKind c) {
  const symbol b("b");
  return !criterion_pieces(c, b).empty();
}

SymbolicLimit symbolic_limit(CriterionKind c) {
  const symbol b("b");
  const std::vector<ex> pieces = criterion_pieces(c, b);
  if (pieces.empty()) throw std::invalid_argument("no known limit for criterion " + std::string(criterion_name(c)));
  return minimise_max(pieces, b);
}

}  // namespace scalcal::symbolic
