// The synthesis front ends on models other than the paper's: random search scores each program by
// the model's own information matrix (checked against evaluate), the exchange and augment reach the
// limits the proofs state for the programs they name.
#include <gtest/gtest.h>

#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/region/augment.hpp"
#include "numeric/synthesis/random_search.hpp"

namespace scalcal {
namespace {

ModelKind model(const char* name) { return *parse_model(name); }

TEST(ModelSynthesis, RandomSearchReportsTheModelsValueOfItsBestProgram) {
  for (const char* m : {"axis6", "bias3", "cubic12"}) {
    const ModelKind kind = model(m);
    const int n = model_parameters(kind) + 4;
    for (CriterionKind c : kCriteria) {
      const RandomSearchResult r = random_search(n, 3000, c, 7, 2, {}, kind);
      ASSERT_EQ(r.program.size(), n);
      EXPECT_NEAR(r.best / evaluate(kind, r.program).value(c), 1.0, 1e-9) << m << " " << criterion_name(c);
      // No program beats the proven limit (proofs/<model>_limits.md).
      EXPECT_GE(r.best, stated_limit(kind, criterion_name(c))->value * (1 - 1e-12)) << m << " " << criterion_name(c);
      // One thread or two: the same programs, the same winner.
      EXPECT_EQ(random_search(n, 3000, c, 7, 1, {}, kind).best, r.best) << m;
    }
  }
}

TEST(ModelSynthesis, RandomSearchDrawsTheSameProgramsForEveryModel) {
  // The stream does not depend on the model: with one program drawn, all models see the same one.
  const RandomSearchResult p9 = random_search(12, 1, CriterionKind::D, 11, 1);
  const RandomSearchResult c12 = random_search(12, 1, CriterionKind::D, 11, 1, {}, model("cubic12"));
  ASSERT_EQ(p9.program.size(), c12.program.size());
  for (int i = 0; i < p9.program.size(); ++i) EXPECT_EQ(p9.program.positions[i], c12.program.positions[i]);
}

TEST(ModelSynthesis, RandomSearchRefusesFewerPositionsThanParameters) {
  EXPECT_THROW(random_search(11, 10, CriterionKind::D, 1, 1, {}, model("cubic12")), std::invalid_argument);
  EXPECT_NO_THROW(random_search(3, 10, CriterionKind::D, 1, 1, {}, model("bias3")));
}

TEST(ModelSynthesis, AugmentCompletesTheSixPositionTestForAxis6) {
  // +x, +y, +z given; the axis6 D limit 729 is attained exactly by the six axis directions
  // (proofs/axis6_limits.md), so three added positions can reach it.
  const Program given{{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)}};
  const AugmentedProgram a = augment_program(given, 3, CriterionKind::D, sphere_region(), model("axis6"));
  EXPECT_FALSE(std::isfinite(a.value_before));
  EXPECT_NEAR(a.value / 729.0, 1.0, 1e-6);
  EXPECT_NEAR(evaluate(model("axis6"), a.program).value(CriterionKind::D) / 729.0, 1.0, 1e-6);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(a.program.positions[i], given.positions[i]);
}

TEST(ModelSynthesis, AugmentForBias3KeepsTheGivenAndReachesTheTightFrameValue) {
  // Any tight frame attains bias3's D limit 27 (N^3 det K with sum eta eta^T = N/3 I).
  const Program given{{Vec3(0, 0, 1)}};
  const AugmentedProgram a = augment_program(given, 3, CriterionKind::D, sphere_region(), model("bias3"));
  EXPECT_NEAR(a.value / 27.0, 1.0, 1e-6);
}

}  // namespace
}  // namespace scalcal
