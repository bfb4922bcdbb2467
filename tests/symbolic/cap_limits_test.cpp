// The exact texts of the caps' limits (symbolic/cap_limits.hpp) against the values the theorems state
// (proofs/cap_es_limits.md, proofs/cap_d_limit.md) and the long double closed forms: each text read
// back by GiNaC's parser is the number the report prints beside it.
#include <gtest/gtest.h>

#include "numeric/region/cap_limits.hpp"
#include "symbolic/cap_limits.hpp"
#include "symbolic/exact.hpp"

namespace sym = scalcal::symbolic;
using scalcal::CriterionKind;

namespace {

scalcal::CapClosedForm form(CriterionKind c, const std::string& spec) {
  const auto f = scalcal::cap_closed_form(c, scalcal::parse_region({spec}));
  EXPECT_TRUE(f) << spec;
  return f ? *f : scalcal::CapClosedForm{};
}

double number(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(); }

}  // namespace

TEST(CapLimitTexts, TheTheoremsValues) {
  EXPECT_EQ(sym::cap_limit_exact(CriterionKind::E, form(CriterionKind::E, "cap:90")), "147");
  EXPECT_EQ(sym::cap_limit_exact(CriterionKind::S, form(CriterionKind::S, "cap:90")), "81");
  EXPECT_EQ(sym::cap_limit_exact(CriterionKind::E, form(CriterionKind::E, "cap:60")), "5283");
  EXPECT_EQ(sym::cap_limit_exact(CriterionKind::S, form(CriterionKind::S, "cap:60:0,0,-1")), "2401");
  EXPECT_EQ(sym::cap_limit_exact(CriterionKind::D, form(CriterionKind::D, "cap:150")), "61509375/4");
  EXPECT_EQ(sym::cap_limit_exact(CriterionKind::D, form(CriterionKind::D, "cap:90")),
            "D(alpha(c), t(c); c) at c = 0, t(c) the root in (0, 1) of 18-29*t^2-26*t^3-29*t^4+10*t^5");
}

// Read back, each text is the printed value (E, S), or names a quintic whose root is the measure's
// inner circle (D); the half-angle is the decimal as written (37.5 degrees is 5/24 Pi).
TEST(CapLimitTexts, ReadBackToTheValues) {
  GiNaC::parser reader;
  for (const char* spec : {"cap:10", "cap:30", "cap:37.5", "cap:45", "cap:72", "cap:99.8", "cap:110"}) {
    for (auto c : {CriterionKind::E, CriterionKind::S}) {
      const auto f = scalcal::cap_closed_form(c, scalcal::parse_region({spec}));
      if (!f) continue;
      const std::string text = sym::cap_limit_exact(c, *f);
      // "FORM at c = COSINE" where the cosine stays cos(...): the form with c replaced.
      const std::size_t at = text.find(" at c = ");
      const GiNaC::ex value =
          at == std::string::npos
              ? reader(text)
              : reader(text.substr(0, at)).subs(reader.get_syms()["c"] == reader(text.substr(at + 8)));
      EXPECT_NEAR(number(value) / f->value, 1.0, 1e-14) << spec << " " << text;
    }
  }
  EXPECT_TRUE(sym::is_zero_exact(sym::cap_cosine(37.5) - GiNaC::cos(GiNaC::numeric(5, 24) * GiNaC::Pi)));
  EXPECT_TRUE(sym::is_zero_exact(sym::cap_cosine(30) - GiNaC::sqrt(GiNaC::ex(3)) / 2));
  const auto d = form(CriterionKind::D, "cap:60");
  const std::string text = sym::cap_limit_exact(CriterionKind::D, d);
  const std::string of = "of ";
  const GiNaC::ex quintic = reader(text.substr(text.rfind(of) + of.size()));
  const GiNaC::symbol t = GiNaC::ex_to<GiNaC::symbol>(reader.get_syms()["t"]);
  EXPECT_LT(std::abs(number(quintic.subs(t == d.heights[2]))), 1e-12) << text;
  EXPECT_NE(sym::cap_limit_exact(CriterionKind::D, form(CriterionKind::D, "cap:10")).find("cos(1/18*Pi)"),
            std::string::npos);
}
