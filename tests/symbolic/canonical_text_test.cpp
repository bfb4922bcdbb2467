// canonical_text: one expression, one text, whatever GiNaC's hash order (which follows symbol
// creation order within a run and the load address of libginac across runs); and the text
// parses back to the same value.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "numeric/criteria/registry.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"
#include "symbolic/limits.hpp"

namespace sym = scalcal::symbolic;
using GiNaC::ex;

namespace {

using Symbols = std::map<std::string, GiNaC::symbol>;

// Symbols a, d, e created in the given order, after `junk` unrelated symbols (which shift the
// serial numbers GiNaC hashes).
Symbols make_symbols(const std::string& order, int junk) {
  for (int i = 0; i < junk; ++i) GiNaC::symbol unrelated("u");
  Symbols s;
  for (char c : order) s.emplace(std::string(1, c), GiNaC::symbol(std::string(1, c)));
  return s;
}

// Expressions of the shapes scalcal prints: expanded sums, factored rational functions, radicals,
// signs and rational contents inside factors, trigonometric terms.
std::vector<ex> shapes(const Symbols& s) {
  const ex a = s.at("a"), d = s.at("d"), e = s.at("e");
  const ex r2 = GiNaC::sqrt(ex(2)), r3 = GiNaC::sqrt(ex(3)), r5 = GiNaC::sqrt(ex(5));
  return {6 * a + 12 * e + 8 * d,
          a * d * e,
          1889568 * GiNaC::pow(2 * a + e, -2) * GiNaC::pow(9 * e + 8 * d, -3) * GiNaC::pow(3 * a + 6 * e + 4 * d, 5),
          GiNaC::factor(GiNaC::expand(-3 * (2 * a + e) * (a - e) * (a + 3) * (d - 2 * e))),
          -(3 * a - 6 * e) * GiNaC::pow(-4 * d - 2 * e, -3) * GiNaC::pow(ex(-2) / 3 * a - e / 3, -2) * d,
          GiNaC::expand(GiNaC::pow(a + d + e + r5, 3)),
          GiNaC::expand((a - r2 * d) * (e + r3) * (1 + r5) / 7),
          45 + 18 * r2,
          6 + 3 * r3,
          ex(GiNaC::numeric(61509375, 4)),
          r2 * a / 2 - r3 * e / 3 + r5 * d / 5 - 1,
          GiNaC::sqrt(a * e + 2 * d) - GiNaC::pow(a + e, ex(3) / 2) + GiNaC::pow(ex(2) / 3, a),
          GiNaC::cos(3 * a * GiNaC::Pi / 180) * e - GiNaC::sin(d) * GiNaC::sin(d) + GiNaC::cos(d),
          (a * a - e * e) / (a * d - 2 * e * d) - GiNaC::pow(a, -1) * e,
          GiNaC::normal((a + e) / (3 * a - 3 * d) + e / (d - a))};
}

std::vector<std::string> texts(const std::vector<ex>& list) {
  std::vector<std::string> out;
  for (const auto& x : list) out.push_back(sym::canonical_text(x));
  return out;
}

// The text parsed back with the same symbols, and the difference simplified to zero.
bool round_trips(const ex& value, const GiNaC::symtab& table) {
  const std::string text = sym::canonical_text(value);
  GiNaC::parser reader(table, true);
  return sym::is_zero_exact(reader(text) - value);
}

GiNaC::symtab table_of(const Symbols& s) {
  GiNaC::symtab t;
  for (const auto& [name, x] : s) t[name] = x;
  return t;
}

// The display splits sqrt(x/y) into sqrt(x)*y^(-1/2), equal only where x, y > 0 (as they are for
// multiplicities), so there equality of two positive values is tested on their squares.
bool same_positive_value(const ex& got, const ex& want, const GiNaC::symtab& table) {
  if (sym::is_zero_exact(got - want)) return true;
  GiNaC::exmap at;
  int value = 2;
  for (const auto& [name, x] : table) at[x] = value++;
  const ex g = GiNaC::evalf(got.subs(at)), w = GiNaC::evalf(want.subs(at));
  return sym::is_zero_exact(GiNaC::pow(got, 2) - GiNaC::pow(want, 2)) && GiNaC::is_a<GiNaC::numeric>(g) &&
         GiNaC::is_a<GiNaC::numeric>(w) && GiNaC::ex_to<GiNaC::numeric>(g).is_positive() &&
         GiNaC::ex_to<GiNaC::numeric>(w).is_positive();
}

TEST(CanonicalText, SameBytesWhateverSymbolOrder) {
  const auto reference = texts(shapes(make_symbols("ade", 0)));
  for (const char* order : {"ade", "aed", "dae", "dea", "ead", "eda"})
    for (int junk : {0, 1, 2, 5, 13, 100}) {
      const auto got = texts(shapes(make_symbols(order, junk)));
      for (std::size_t i = 0; i < got.size(); ++i)
        EXPECT_EQ(got[i], reference[i]) << "order " << order << ", " << junk << " symbols before, shape " << i;
    }
}

TEST(CanonicalText, KnownForms) {
  const auto s = make_symbols("eda", 3);
  const auto t = texts(shapes(s));
  EXPECT_EQ(t[0], "6*a+8*d+12*e");
  EXPECT_EQ(t[1], "a*d*e");
  EXPECT_EQ(t[2], "1889568*(2*a+e)^(-2)*(3*a+4*d+6*e)^5*(8*d+9*e)^(-3)");
  EXPECT_EQ(t[4], "27/8*d*(2*a+e)^(-2)*(2*d+e)^(-3)*(a-2*e)");  // signs and contents out of the sums
  EXPECT_EQ(t[7], "45+18*sqrt(2)");
  EXPECT_EQ(t[9], "61509375/4");
}

TEST(CanonicalText, RoundTripKeepsValue) {
  const auto s = make_symbols("dea", 4);
  for (const auto& x : shapes(s)) EXPECT_TRUE(round_trips(x, table_of(s))) << sym::canonical_text(x);
}

// Every closed form the families and the limits produce: criteria, K's diagonal, eigenvalues.
TEST(CanonicalText, RoundTripFamilyClosedForms) {
  const std::vector<std::pair<std::string, std::vector<std::string>>> members = {
      {"octahedral", {"axes=a", "edges=e", "diagonals=d"}},
      {"octahedral", {"axes=2", "edges=1", "diagonals=3"}},
      {"octahedral", {"axes=a", "edges=1", "diagonals=d"}},
      {"rotation", {"k=3", "phase=10"}},
      {"rotation", {"k=4", "phase=10"}},
      {"rotation", {"k=7", "phase=p"}},
      {"dodecahedral", {}},
      {"icosahedral", {}}};
  int checked = 0;
  for (const auto& [name, settings] : members) {
    const auto& f = sym::find_family(name);
    const auto p = sym::parse_params(f, settings);
    GiNaC::symtab table;
    for (const auto& [key, v] : p)
      if (GiNaC::is_a<GiNaC::symbol>(v)) table[GiNaC::ex_to<GiNaC::symbol>(v).get_name()] = v;
    const auto in = f.instance(p);
    const auto c = sym::exact_criteria(in.M, in.N);
    std::vector<ex> forms{in.N};
    for (const auto* v :
         {&c.at("D"), &c.at("A"), &c.at("E"), &c.at("S"), &c.theta_bias, &c.theta_scale, &c.theta_nonorth})
      if (v->exact) forms.insert(forms.end(), v->candidates.begin(), v->candidates.end());
    forms.insert(forms.end(), c.K_diagonal.begin(), c.K_diagonal.end());
    if (c.at("E").exact) forms.insert(forms.end(), c.eigenvalues.begin(), c.eigenvalues.end());
    for (const auto& x : forms) {
      EXPECT_TRUE(round_trips(x, table)) << name << ": " << sym::canonical_text(x);
      ++checked;
    }
  }
  for (auto k : scalcal::kCriteria) {
    const auto l = sym::symbolic_limit(k);
    for (const auto& x : {l.value, l.b, l.x4}) {
      EXPECT_TRUE(round_trips(x, {})) << sym::canonical_text(x);
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

// ExactValue::str() prints the displayed (factored) forms; each piece of max(...) parses back to
// its candidate.
TEST(CanonicalText, RoundTripDisplayedCriteria) {
  const auto& f = sym::find_family("octahedral");
  const auto p = sym::parse_params(f, {"axes=a", "edges=e", "diagonals=d"});
  GiNaC::symtab table;
  for (const auto& [key, v] : p) table[GiNaC::ex_to<GiNaC::symbol>(v).get_name()] = v;
  const auto in = f.instance(p);
  const auto c = sym::exact_criteria(in.M, in.N);
  for (const auto* v :
       {&c.at("D"), &c.at("A"), &c.at("E"), &c.at("S"), &c.theta_bias, &c.theta_scale, &c.theta_nonorth}) {
    std::string text = v->str();
    std::vector<std::string> pieces;
    if (text.rfind("max(", 0) == 0) {
      text = text.substr(4, text.size() - 5);
      for (std::size_t at = 0, next; at <= text.size(); at = next + 2) {
        next = std::min(text.find(", ", at), text.size());
        pieces.push_back(text.substr(at, next - at));
      }
    } else {
      pieces.push_back(text);
    }
    ASSERT_EQ(pieces.size(), v->candidates.size()) << v->str();
    GiNaC::parser reader(table, true);
    for (std::size_t i = 0; i < pieces.size(); ++i)
      EXPECT_TRUE(same_positive_value(reader(pieces[i]), v->candidates[i], table)) << pieces[i];
  }
}

// The whole family pipeline twice in one process, parameters given (so symbols created) in
// another order and after unrelated symbols: the printed closed forms are the same bytes.
TEST(CanonicalText, FamilyOutputIndependentOfSymbolOrder) {
  const auto& f = sym::find_family("octahedral");
  auto printed = [&](const std::vector<std::string>& settings, int junk) {
    make_symbols("", junk);
    const auto p = sym::parse_params(f, settings);
    const auto in = f.instance(p);
    const auto c = sym::exact_criteria(in.M, in.N);
    std::vector<std::string> out{sym::canonical_text(in.N)};
    for (const auto* v :
         {&c.at("D"), &c.at("A"), &c.at("E"), &c.at("S"), &c.theta_bias, &c.theta_scale, &c.theta_nonorth})
      out.push_back(v->str());
    return out;
  };
  const auto first = printed({"axes=a", "edges=e", "diagonals=d"}, 0);
  EXPECT_EQ(first[0], "6*a+8*d+12*e");
  EXPECT_EQ(first[1], "1889568*(2*a+e)^(-2)*(3*a+4*d+6*e)^5*(8*d+9*e)^(-3)");
  for (int junk : {1, 7, 40}) {
    EXPECT_EQ(printed({"diagonals=d", "edges=e", "axes=a"}, junk), first) << junk;
    EXPECT_EQ(printed({"edges=e", "axes=a", "diagonals=d"}, junk), first) << junk;
  }
}

}  // namespace
