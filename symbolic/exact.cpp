// Exact moment matrices. Rationalising denominators matters because jig coordinates such as
// 1/sqrt(1 + phi^2) leave sqrt(5) in denominators, where normal() alone cannot see that two
// forms are equal.
#include "symbolic/exact.hpp"

#include <algorithm>
#include <optional>
#include <regex>

#include <cln/integer_io.h>
#include <cln/rational.h>
#include <cln/real.h>

namespace scalcal::symbolic {

using GiNaC::ex;
using GiNaC::matrix;

matrix design_row(const Point& eta) {
  const ex& x = eta[0];
  const ex& y = eta[1];
  const ex& z = eta[2];
  return matrix(9, 1, GiNaC::lst{x, y, z, x * x, y * y, z * z, x * y, y * z, z * x});
}

namespace {

// The first square root of a number (power(p, 1/2) or power(p, -1/2) with p a positive
// rational, or such a power of a sum) found in e, or 0 when there is none.
ex find_radical(const ex& e) {
  if (GiNaC::is_a<GiNaC::power>(e)) {
    const ex expo = e.op(1);
    if (GiNaC::is_a<GiNaC::numeric>(expo) && !GiNaC::ex_to<GiNaC::numeric>(expo).is_integer() &&
        (GiNaC::ex_to<GiNaC::numeric>(expo) * 2).is_integer() && GiNaC::is_a<GiNaC::numeric>(e.op(0)))
      return GiNaC::sqrt(e.op(0));
  }
  for (std::size_t i = 0; i < e.nops(); ++i) {
    ex r = find_radical(e.op(i));
    if (!r.is_zero()) return r;
  }
  return 0;
}

}  // namespace

ex canonical(const ex& e) {
  // sin^2 = 1 - cos^2 makes polynomials in the cosine and sine of one angle canonical (the
  // rotation family's ring sums hold cos(n phase) and sin(n phase)).
  const ex w0 = GiNaC::wild(0);
  const ex reduced = GiNaC::expand(e).subs(GiNaC::pow(GiNaC::sin(w0), 2) == 1 - GiNaC::pow(GiNaC::cos(w0), 2),
                                           GiNaC::subs_options::algebraic);
  ex nd = GiNaC::normal(GiNaC::expand(reduced)).numer_denom();
  ex num = GiNaC::expand(nd.op(0));
  ex den = GiNaC::expand(nd.op(1));
  // Multiply by conjugates until the denominator holds no square root of a number; each pass
  // removes one radical r (den = A + B r with A, B free of r, as r^2 is rational).
  for (int pass = 0; pass < 16; ++pass) {
    const ex r = find_radical(den);
    if (r.is_zero()) break;
    const GiNaC::symbol s("r");
    const ex d = GiNaC::expand(den.subs(r == s).subs(GiNaC::pow(s, -1) == s / GiNaC::pow(r, 2)));
    const ex A = d.coeff(s, 0), B = d.coeff(s, 1);
    if (d.degree(s) > 1 || d.ldegree(s) < 0) break;  // not linear in r: leave it
    const ex conj = A - B * r;
    num = GiNaC::expand(num * conj);
    den = GiNaC::expand(den * conj);
  }
  if (den.is_equal(ex(1))) return num;
  if (GiNaC::is_a<GiNaC::numeric>(den)) return GiNaC::expand(num / den);
  return num / den;
}

matrix moment_matrix(const std::vector<WeightedPoint>& points) {
  matrix M(9, 9);
  std::vector<matrix> rows;
  rows.reserve(points.size());
  for (const auto& p : points) rows.push_back(design_row(p.eta));
  for (int r = 0; r < 9; ++r)
    for (int c = r; c < 9; ++c) {
      ex sum = 0;
      for (std::size_t i = 0; i < points.size(); ++i) sum += points[i].weight * rows[i](r, 0) * rows[i](c, 0);
      const ex v = canonical(sum);
      M(r, c) = v;
      M(c, r) = v;
    }
  return M;
}

MomentFunction point_moments(std::vector<WeightedPoint> points) {
  return [points = std::move(points)](int a, int b, int c) {
    // x^0 is 1 even at x = 0 (GiNaC leaves pow(0, 0) undefined).
    const auto power = [](const ex& x, int k) { return k == 0 ? ex(1) : GiNaC::pow(x, k); };
    ex sum = 0;
    for (const auto& p : points) sum += p.weight * power(p.eta[0], a) * power(p.eta[1], b) * power(p.eta[2], c);
    return canonical(sum);
  };
}

namespace {
struct ExactDecimals : GiNaC::map_function {
  ex operator()(const ex& e) override {
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
      const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
      if (n.is_real() && !n.is_rational()) return GiNaC::numeric(cln::rationalize(cln::realpart(n.to_cl_N())));
      return e;
    }
    return e.map(*this);
  }
};
}  // namespace

ex exact_decimals(const ex& e) {
  ExactDecimals exact;
  return exact(e);
}

namespace {

// The exact number a decimal literal names ([+-]digits[.digits][e[+-]digits], spaces around it),
// or nothing when the text is not one.
std::optional<cln::cl_RA> decimal_literal(const std::string& text) {
  static const std::regex literal(R"(\s*([+-]?)(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?\s*)");
  std::smatch m;
  if (!std::regex_match(text, m, literal) || (m[2].length() == 0 && m[3].length() == 0)) return std::nullopt;
  const std::string digits = m[2].str() + m[3].str();
  const std::string trimmed = digits.substr(std::min(digits.find_first_not_of('0'), digits.size()));
  const cln::cl_I mantissa =
      trimmed.empty() ? cln::cl_I(0) : cln::read_integer(10, 0, trimmed.c_str(), 0, trimmed.size());
  // The exponent's size is bounded before (a decimal exponent above 1000 is refused where text is read).
  const long exponent = (m[4].length() ? std::stol(m[4].str()) : 0) - static_cast<long>(m[3].length());
  const cln::cl_RA scale = cln::expt(cln::cl_RA(10), exponent);
  return m[1] == "-" ? cln::cl_RA(-mantissa * scale) : cln::cl_RA(mantissa * scale);
}

}  // namespace

ex reduced_degrees(const ex& value, const std::string& text) {
  if (!GiNaC::is_a<GiNaC::numeric>(value) || !GiNaC::ex_to<GiNaC::numeric>(value).is_real()) return value;
  const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(value);
  const std::optional<cln::cl_RA> literal = decimal_literal(text);
  const cln::cl_RA exact = literal ? *literal : cln::rational(cln::realpart(n.to_cl_N()));
  const cln::cl_RA reduced = exact - cln::cl_RA(360) * cln::cl_RA(cln::floor1(exact / 360));
  const GiNaC::numeric out(reduced);
  return n.is_rational() ? ex(out) : ex(GiNaC::evalf(out));
}

}  // namespace scalcal::symbolic
