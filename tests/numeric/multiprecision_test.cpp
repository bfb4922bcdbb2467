// The numeric core is templated on the scalar: the same evaluation at 50 digits must reproduce
// the closed forms derived by hand to 45 digits (double could only give 15).
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/criteria/registry.hpp"

namespace scalcal {
namespace {

using mp50 = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<50>, boost::multiprecision::et_off>;

mp50 relative_error(const mp50& a, const mp50& b) {
  using boost::multiprecision::abs;
  return abs(a / b - mp50(1));
}

TEST(Multiprecision, Classic18AtFiftyDigits) {
  const auto ev = evaluate(ProgramTpl<mp50>::classic18());
  EXPECT_EQ(ev.rank, 9);
  EXPECT_LT(relative_error(ev.value(CriterionKind::D), mp50(17006112)), mp50("1e-45"));
  EXPECT_LT(relative_error(ev.value(CriterionKind::A), mp50(78)), mp50("1e-45"));
}

TEST(Multiprecision, JigsReachTheDLimitToFortyFiveDigits) {
  const mp50 limit = mp50(61509375) / mp50(4);
  EXPECT_LT(relative_error(evaluate(ProgramTpl<mp50>::icosahedral()).value(CriterionKind::D), limit), mp50("1e-45"));
  EXPECT_LT(relative_error(evaluate(ProgramTpl<mp50>::dodecahedral()).value(CriterionKind::D), limit), mp50("1e-45"));
  EXPECT_LT(relative_error(evaluate(ProgramTpl<mp50>::rotation(7, mp50(10))).value(CriterionKind::D),
                           mp50(81) * mp50(13824) * mp50(576) / mp50(25)),
            mp50("1e-45"));
}

TEST(Multiprecision, DoubleAndFiftyDigitsAgree) {
  const Program p = Program::random(23, 11);
  const auto lo = evaluate(p);
  const auto hi = evaluate(p.cast<mp50>());
  EXPECT_NEAR(lo.value(CriterionKind::D) / static_cast<double>(hi.value(CriterionKind::D)), 1.0, 1e-12);
  EXPECT_NEAR(lo.value(CriterionKind::E) / static_cast<double>(hi.value(CriterionKind::E)), 1.0, 1e-12);
  EXPECT_NEAR(lo.value(CriterionKind::S) / static_cast<double>(hi.value(CriterionKind::S)), 1.0, 1e-12);
}

// Every program is bounded below by the limits (the limits are infima over all measures).
TEST(Limits, CatalogueProgramsRespectTheLimits) {
  for (const Program& p : {Program::classic18(), Program::icosahedral(), Program::random(30, 5),
                           Program::octahedral(1, 1, 1), Program::rotation(3)}) {
    const Evaluation ev = evaluate(p);
    EXPECT_GE(ev.value(CriterionKind::D), criterion_limit(CriterionKind::D).value * (1 - 1e-12));
    EXPECT_GE(ev.value(CriterionKind::A), criterion_limit(CriterionKind::A).value * (1 - 1e-12));
    EXPECT_GE(ev.value(CriterionKind::E), criterion_limit(CriterionKind::E).value * (1 - 1e-12));
    EXPECT_GE(ev.value(CriterionKind::S), criterion_limit(CriterionKind::S).value * (1 - 1e-12));
  }
}

}  // namespace
}  // namespace scalcal
