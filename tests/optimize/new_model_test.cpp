// A model is one file (numeric/model/bias3.hpp, born as a test-only file): evaluation, Riemannian
// Newton, Ipopt (all three forms) and the MPFR polish run on it unchanged. Expected values are the
// hand-derived limits of bias3 (27, 9, 3, 3 for D, A, E, S: trace M = N), not numbers taken from scalcal.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/model/bias3.hpp"
#include "numeric/polish/polish_form.hpp"
#include "numeric/synthesis/ipopt_local.hpp"
#include "numeric/synthesis/newton_local.hpp"
#include "numeric/synthesis/synthesize.hpp"

namespace scalcal {
namespace {

TEST(NewModel, EvaluationOfTheAxesMatchesTheHandLimits) {
  const auto ev = (evaluate<Bias3Model>)(Program::octahedral(1, 0, 0));  // M = 2 I, N = 6
  ASSERT_EQ(ev.rank, 3);
  EXPECT_NEAR(ev.value(CriterionKind::D), 27.0, 1e-12);
  EXPECT_NEAR(ev.value(CriterionKind::A), 9.0, 1e-12);
  EXPECT_NEAR(ev.value(CriterionKind::E), 3.0, 1e-12);
  EXPECT_NEAR(ev.value(CriterionKind::S), 3.0, 1e-12);
  EXPECT_NEAR(ev.theta_bias, std::sqrt(3.0), 1e-12);
  EXPECT_TRUE(std::isnan(ev.theta_scale));  // the model has no scale-factor group
}

TEST(NewModel, APlanarProgramLosesTheNormalBias) {
  Program planar;
  for (int i = 0; i < 8; ++i) planar.positions.emplace_back(std::cos(0.7 * i), std::sin(0.7 * i), 0.0);
  const auto ev = (evaluate<Bias3Model>)(planar);
  EXPECT_EQ(ev.rank, 2);
  ASSERT_EQ(ev.unidentifiable.size(), 1u);
  EXPECT_EQ(Bias3Model::parameter_names[static_cast<std::size_t>(ev.unidentifiable[0])], "bias_z");
}

TEST(NewModel, NewtonReachesTheDAndALimits) {
  for (std::uint64_t seed : {3u, 4u, 5u}) {
    const Program start = Program::random(7, seed);
    EXPECT_NEAR((optimize_with_newton<DCriterion, Bias3Model>)(start).value, 27.0, 1e-8) << seed;
    EXPECT_NEAR((optimize_with_newton<ACriterion, Bias3Model>)(start).value, 9.0, 1e-8) << seed;
  }
}

TEST(NewModel, IpoptReachesTheLimitsOfEveryForm) {
  const Program start = Program::random(7, 11);
  EXPECT_NEAR((optimize_with_ipopt<DCriterion, Bias3Model>)(start).value, 27.0, 1e-6);
  EXPECT_NEAR((optimize_with_ipopt<ECriterion, Bias3Model>)(start).value, 3.0, 1e-6);
  EXPECT_NEAR((optimize_with_ipopt<SCriterion, Bias3Model>)(start).value, 3.0, 1e-6);
}

TEST(NewModel, TheMultistartRunsOnIt) {
  SynthesisOptions o;
  o.positions = 5;
  o.starts = 3;
  o.threads = 1;
  const SynthesisResult r = (synthesize<DCriterion, Bias3Model>)(o);
  EXPECT_NEAR(r.value, 27.0, 1e-8);
  EXPECT_EQ(r.hits, 3);
  SynthesisOptions too_few;
  too_few.positions = 2;  // N < P
  EXPECT_THROW((synthesize<DCriterion, Bias3Model>)(too_few), std::invalid_argument);
}

TEST(NewModel, ThePolishGivesTheLimitsTo40Digits) {
  const Program d = optimize_with_newton<DCriterion, Bias3Model>(Program::random(7, 3)).program;
  const PolishResult pd = (polish<DCriterion, Bias3Model>)(d, PolishOptions{40, 40});
  ASSERT_TRUE(pd.converged()) << pd.residual;
  EXPECT_EQ(pd.value_digits.substr(0, 42), "27.00000000000000000000000000000000000000");
  const Program s = (optimize_with_ipopt<SCriterion, Bias3Model>)(Program::random(7, 11)).program;
  const PolishResult ps = (polish<SCriterion, Bias3Model>)(s, PolishOptions{40, 40});
  ASSERT_TRUE(ps.converged()) << ps.residual;
  EXPECT_EQ(ps.value_digits.substr(0, 41), "3.000000000000000000000000000000000000000");
  const Program e = (optimize_with_ipopt<ECriterion, Bias3Model>)(Program::random(7, 11)).program;
  const PolishResult pe = (polish<ECriterion, Bias3Model>)(e, PolishOptions{40, 40});
  ASSERT_TRUE(pe.converged()) << pe.residual << " " << pe.summary.message;
  EXPECT_EQ(pe.value_digits.substr(0, 41), "3.000000000000000000000000000000000000000");
}

}  // namespace
}  // namespace scalcal
