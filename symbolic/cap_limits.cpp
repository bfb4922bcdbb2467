// The exact text of a cap's proven limit (cap_limits.hpp).
#include "symbolic/cap_limits.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "symbolic/exact.hpp"

namespace scalcal::symbolic {
namespace {

using GiNaC::ex;
using GiNaC::numeric;

// The shortest decimal that reads back to x, as an exact rational ("37.5" -> 75/2).
numeric shortest_rational(double x) {
  char text[64];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*e", digits - 1, x);
    if (std::strtod(text, nullptr) == x) break;
  }
  // text is d.ddddde[+-]XX: the mantissa's digits over 10^(digits - 1 - exponent).
  std::string s(text);
  const std::size_t e = s.find('e');
  const int exponent = std::atoi(s.c_str() + e + 1);
  std::string mantissa = s.substr(0, e);
  const bool negative = mantissa[0] == '-';
  if (negative) mantissa.erase(0, 1);
  std::string digits;
  for (char ch : mantissa)
    if (ch != '.') digits += ch;
  numeric out(digits.c_str());
  const int scale = static_cast<int>(digits.size()) - 1 - exponent;
  out = scale >= 0 ? out / numeric(10).power(scale) : out * numeric(10).power(-scale);
  return negative ? -out : out;
}

// P(c, t) of Theorem 8, whose root in (c, 1) is the inner circle's height.
ex quintic(const ex& c, const ex& t) {
  return 10 * (3 * c + 1) * GiNaC::pow(t, 5) + (39 * c * c + 6 * c - 29) * GiNaC::pow(t, 4) +
         2 * (24 * GiNaC::pow(c, 3) + 3 * c * c - 54 * c - 13) * GiNaC::pow(t, 3) -
         (39 * GiNaC::pow(c, 4) - 6 * GiNaC::pow(c, 3) - 48 * c * c + 18 * c + 29) * t * t -
         2 * c * (c + 3) * (8 * c * c - 13) * t - GiNaC::pow(c + 3, 2) * (c * c - 2);
}

bool has_function(const ex& e) { return e.has(GiNaC::cos(GiNaC::wild())); }

}  // namespace

ex cap_cosine(double half_angle_deg) { return GiNaC::cos(shortest_rational(half_angle_deg) * GiNaC::Pi / 180); }

ex cap_limit_expression(CriterionKind criterion, const CapClosedForm& form) {
  const ex c = cap_cosine(form.half_angle_deg);
  if (criterion == CriterionKind::E)
    return canonical((3 * GiNaC::pow(c, 4) + 36 * GiNaC::pow(c, 3) + 194 * c * c + 260 * c + 147) /
                     GiNaC::pow(1 - c, 4));
  if (criterion == CriterionKind::S) return canonical(GiNaC::pow((3 + c) / (1 - c), 4));
  if (criterion == CriterionKind::D && form.sphere_limit) return numeric(61509375, 4);
  throw std::invalid_argument("cap_limit_expression: no closed-form expression (D below 133.62 degrees)");
}

std::string cap_limit_exact(CriterionKind criterion, const CapClosedForm& form) {
  const ex c = cap_cosine(form.half_angle_deg);
  const std::string ct = canonical_text(c);
  // At a cosine GiNaC keeps as cos(...) the expanded form would repeat it a dozen times: the theorem's form.
  if (criterion == CriterionKind::E && has_function(c)) return "(3*c^4+36*c^3+194*c^2+260*c+147)/(1-c)^4 at c = " + ct;
  if (criterion == CriterionKind::S && has_function(c)) return "((3+c)/(1-c))^4 at c = " + ct;
  if (criterion != CriterionKind::D || form.sphere_limit) return canonical_text(cap_limit_expression(criterion, form));
  if (has_function(c))  // cos(1/18*Pi): the quintic's coefficients would be long; the theorem names it
    return "D(alpha(c), t(c); c) at c = " + ct + ", t(c) the root in (c, 1) of P(c, t)";
  const GiNaC::symbol t("t");
  return "D(alpha(c), t(c); c) at c = " + ct + ", t(c) the root in (" + ct + ", 1) of " +
         canonical_text(canonical(quintic(c, t)));
}

}  // namespace scalcal::symbolic
