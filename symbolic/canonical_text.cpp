// canonical_text: expressions printed in an order of our own. GiNaC sorts the operands of sums
// and products by hash, and GiNaC 1.8 seeds every hash with the address of typeid(T).name()
// inside libginac.so, which address-space randomisation moves on each run; symbol hashes also
// mix in creation serials. So `ostream << e` changes its term order between runs (and between
// symbols created in another order). Here the order comes only from the printed text.
//
// Sorting alone is not enough: GiNaC chooses the sign of a sum inside a product by its own term
// order (mul::eval strips the unit, factor() and normal() likewise), so (9*e+8*d)^3 may come back
// as -(-9*e-8*d)^3. A sum raised to an integer power is printed as unit * primitive, with the
// first term's coefficient positive and rational coefficients coprime integers (split_unit).
// The normalisation lives in the printer, not in a rebuilt ex, because GiNaC re-strips units.
// Sums are printed expanded: factor() may return a factor half-collected in a variable of its
// choosing (162*a^2+...+81*(4*d+7*a)*e), a shape that also varies between runs.
#include <algorithm>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "symbolic/exact.hpp"

namespace scalcal::symbolic {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

namespace {

std::string print(const ex& e);
std::pair<ex, ex> split_unit(const ex& sum);

std::string gin_text(const ex& e) {
  std::ostringstream s;
  s << e;
  return s.str();
}

// Built by appending: GCC 12 warns falsely (-Wrestrict) on "(" + std::string.
std::string wrap(const char* open, const std::string& s) {
  std::string out(open);
  out += s;
  out += ')';
  return out;
}

bool is_rational_number(const ex& e) { return is_a<numeric>(e) && ex_to<numeric>(e).is_rational(); }
bool is_real_number(const ex& e) { return is_a<numeric>(e) && ex_to<numeric>(e).is_real(); }

// One factor b^x of a product. Factors sort numbers (radicals) first, then constants, symbols,
// functions and parenthesised sums; then by base text, higher exponent first.
struct Factor {
  int kind;
  std::string base;
  ex exponent;
  std::string text;
};

int kind_of(const ex& base) {
  if (is_a<numeric>(base)) return 0;
  if (is_a<GiNaC::constant>(base)) return 1;
  if (is_a<GiNaC::symbol>(base)) return 2;
  if (is_a<GiNaC::function>(base)) return 3;
  return 4;
}

// -1, 0, 1 as a < b; real numbers numerically, anything else by text.
int compare_values(const ex& a, const ex& b) {
  if (is_real_number(a) && is_real_number(b)) return ex_to<numeric>(a).compare(ex_to<numeric>(b));
  if (is_real_number(a) != is_real_number(b)) return is_real_number(a) ? -1 : 1;
  const std::string ta = print(a), tb = print(b);
  return ta < tb ? -1 : ta > tb ? 1 : 0;
}

bool factor_less(const Factor& a, const Factor& b) {
  if (a.kind != b.kind) return a.kind < b.kind;
  if (a.base != b.base) return a.base < b.base;
  if (const int c = compare_values(a.exponent, b.exponent)) return c > 0;
  return a.text < b.text;
}

// The base as it stands before "^": atoms bare, anything with operators in parentheses.
std::string base_text(const ex& b) {
  const bool bare = is_a<GiNaC::symbol>(b) || is_a<GiNaC::constant>(b) || is_a<GiNaC::function>(b) ||
                    (is_a<numeric>(b) && ex_to<numeric>(b).is_pos_integer());
  return bare ? print(b) : wrap("(", print(b));
}

Factor make_factor(const ex& base, const ex& exponent) {
  Factor f{kind_of(base), print(base), exponent, {}};
  if (exponent.is_equal(ex(1))) {
    f.text = is_a<GiNaC::add>(base) || is_a<GiNaC::mul>(base) ? wrap("(", f.base) : f.base;
  } else if (exponent.is_equal(ex(1) / 2)) {
    f.text = wrap("sqrt(", f.base);
  } else {
    const bool bare_exp = (is_a<numeric>(exponent) && ex_to<numeric>(exponent).is_nonneg_integer()) ||
                          is_a<GiNaC::symbol>(exponent) || is_a<GiNaC::constant>(exponent);
    f.text = base_text(base) + "^" + (bare_exp ? print(exponent) : wrap("(", print(exponent)));
  }
  return f;
}

// A term of a sum: numeric coefficient times sorted factors.
struct Term {
  ex coeff;
  std::vector<Factor> factors;
  ex degree;  // total degree in the symbols
  std::string text;
};

Term make_term(const ex& t) {
  Term term{1, {}, 0, {}};
  auto take = [&](const ex& f) {
    if (is_a<numeric>(f)) {
      term.coeff = term.coeff * f;
      return;
    }
    ex base = is_a<GiNaC::power>(f) ? f.op(0) : f;
    const ex expo = is_a<GiNaC::power>(f) ? f.op(1) : ex(1);
    if (is_a<GiNaC::add>(base)) base = GiNaC::expand(base);
    if (is_a<GiNaC::add>(base) && is_a<numeric>(expo) && ex_to<numeric>(expo).is_integer()) {
      const auto [unit, primitive] = split_unit(base);
      term.coeff = term.coeff * GiNaC::pow(unit, expo);
      base = primitive;
    }
    term.factors.push_back(make_factor(base, expo));
  };
  if (is_a<GiNaC::mul>(t))
    for (std::size_t i = 0; i < t.nops(); ++i) take(t.op(i));
  else
    take(t);
  std::sort(term.factors.begin(), term.factors.end(), factor_less);
  for (const auto& f : term.factors)
    if (f.kind == 2 && is_real_number(f.exponent)) term.degree = term.degree + f.exponent;
  std::string rest;
  for (const auto& f : term.factors) rest += (rest.empty() ? "" : "*") + f.text;
  const numeric c = ex_to<numeric>(term.coeff);
  if (rest.empty()) {
    term.text = gin_text(c);
  } else if (c.is_equal(1)) {
    term.text = rest;
  } else if (c.is_equal(-1)) {
    term.text = std::string(1, '-').append(rest);
  } else {
    const bool plain = c.is_real();  // integers, rationals and floats print without parentheses
    term.text = (plain ? gin_text(c) : wrap("(", gin_text(c))) + "*" + rest;
  }
  return term;
}

// Terms by degree, then by their symbolic factors (names ascending, higher power first), then by
// numbers such as sqrt(2), then by coefficient; the text breaks any tie left.
bool term_less(const Term& a, const Term& b) {
  if (const int c = compare_values(a.degree, b.degree)) return c < 0;
  auto part = [](const Term& t, bool symbolic) {
    std::vector<Factor> out;
    for (const auto& f : t.factors)
      if ((f.kind >= 2) == symbolic) out.push_back(f);
    return out;
  };
  for (bool symbolic : {true, false}) {
    const auto fa = part(a, symbolic), fb = part(b, symbolic);
    if (std::lexicographical_compare(fa.begin(), fa.end(), fb.begin(), fb.end(), factor_less)) return true;
    if (std::lexicographical_compare(fb.begin(), fb.end(), fa.begin(), fa.end(), factor_less)) return false;
  }
  if (const int c = compare_values(a.coeff, b.coeff)) return c < 0;
  return a.text < b.text;
}

std::vector<Term> sorted_terms(const ex& sum) {
  std::vector<Term> terms;
  for (std::size_t i = 0; i < sum.nops(); ++i) terms.push_back(make_term(sum.op(i)));
  std::sort(terms.begin(), terms.end(), term_less);
  return terms;
}

std::string print(const ex& e) {
  if (is_a<GiNaC::add>(e)) {
    const ex x = GiNaC::expand(e);
    if (!is_a<GiNaC::add>(x)) return print(x);
    std::string s;
    for (const auto& t : sorted_terms(x)) s += (s.empty() || t.text[0] == '-' ? "" : "+") + t.text;
    return s;
  }
  if (is_a<GiNaC::mul>(e) || is_a<GiNaC::power>(e)) return make_term(e).text;
  if (is_a<GiNaC::function>(e)) {
    std::string s = ex_to<GiNaC::function>(e).get_name() + "(";
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (i) s += ',';
      s += print(e.op(i));
    }
    return s + ")";
  }
  return gin_text(e);  // numbers, symbols, constants: their text does not depend on order
}

// sum = unit * primitive, the unit a real number making the first term's coefficient positive
// and, when every coefficient is rational, the coefficients coprime integers.
std::pair<ex, ex> split_unit(const ex& sum) {
  const auto terms = sorted_terms(sum);
  bool rational = true;
  for (const auto& t : terms) rational = rational && is_rational_number(t.coeff);
  numeric unit = 1;
  if (rational) {
    numeric num = 0, den = 1;
    for (const auto& t : terms) {
      const numeric c = ex_to<numeric>(t.coeff);
      num = GiNaC::gcd(num, GiNaC::abs(c.numer()));
      den = GiNaC::lcm(den, c.denom());
    }
    unit = num / den;
  }
  if (const ex lead = terms.front().coeff; is_real_number(lead) && ex_to<numeric>(lead).is_negative()) unit = -unit;
  if (unit.is_equal(1)) return {1, sum};
  ex primitive = 0;
  for (std::size_t i = 0; i < sum.nops(); ++i) primitive += sum.op(i) / unit;
  return {unit, primitive};
}

}  // namespace

std::string canonical_text(const ex& e) { return print(e); }

}  // namespace scalcal::symbolic
