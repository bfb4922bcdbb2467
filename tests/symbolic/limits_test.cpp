// The symbolic limits against the lead's hand derivation in numeric/limits.hpp (exact strings
// parsed by GiNaC), and against the numeric core on programs that attain them.
#include <gtest/gtest.h>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/criteria/registry.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"

namespace sym = scalcal::symbolic;

TEST(SymbolicLimits, AgreeWithNumericLimitsHeader) {
  GiNaC::parser reader;
  for (auto c : scalcal::kCriteria) {
    const auto lim = sym::symbolic_limit(c);
    const auto stated = scalcal::criterion_limit<double>(c);
    EXPECT_TRUE(sym::is_zero_exact(lim.value - reader(std::string(stated.exact)))) << scalcal::criterion_name(c);
    EXPECT_NEAR(GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(lim.b)).to_double(), stated.moment_b, 1e-15);
  }
}

// Attainers computed by the numeric core: the icosahedral jig reaches D (a 4-design), the 12
// edge positions reach E = 12, and no random program goes below any limit.
TEST(SymbolicLimits, AttainedAndNeverBeaten) {
  using scalcal::CriterionKind;
  const double D = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(sym::symbolic_limit(CriterionKind::D).value)).to_double();
  const double E = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(sym::symbolic_limit(CriterionKind::E).value)).to_double();
  EXPECT_NEAR(scalcal::evaluate(scalcal::Program::icosahedral()).value(CriterionKind::D) / D, 1.0, 1e-12);
  EXPECT_NEAR(scalcal::evaluate(scalcal::Program::octahedral(0, 1, 0)).value(CriterionKind::E) / E, 1.0, 1e-12);
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto ev = scalcal::evaluate(scalcal::Program::random(30, seed));
    for (auto c : scalcal::kCriteria) {
      const double lim = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(sym::symbolic_limit(c).value)).to_double();
      EXPECT_GE(ev.value(c), lim);
    }
  }
}
