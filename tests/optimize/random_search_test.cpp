// The hot loop's arithmetic (moments, LDL^T) against the eigen-decomposition of evaluate(), and
// the search's independence from the number of threads.
#include <gtest/gtest.h>

#include <cmath>

#include "numeric/evaluation.hpp"
#include "numeric/random_search_kernel.hpp"
#include "numeric/synthesis.hpp"

namespace scalcal {
namespace {

TEST(RandomSearchKernel, AgreesWithEvaluate) {
  for (int n : {9, 13, 18, 31}) {
    const Program p = Program::random(n, static_cast<std::uint64_t>(n));
    std::vector<double> eta;
    for (const auto& e : p.positions) eta.insert(eta.end(), {e(0), e(1), e(2)});
    const Evaluation ev = evaluate(p);
    EXPECT_NEAR(score_positions(eta.data(), n, CriterionKind::D) / ev.D, 1.0, 1e-10);
    EXPECT_NEAR(score_positions(eta.data(), n, CriterionKind::A) / ev.A, 1.0, 1e-10);
    EXPECT_NEAR(score_positions(eta.data(), n, CriterionKind::E) / ev.E, 1.0, 1e-10);
    EXPECT_NEAR(score_positions(eta.data(), n, CriterionKind::S) / ev.S, 1.0, 1e-10);
  }
}

TEST(RandomSearchKernel, Classic18ByHand) {
  // The 18-position program: D = 17006112 and A = 78 (derived by hand in the paper's Fig. 1 case).
  const Program p = Program::classic18();
  std::vector<double> eta;
  for (const auto& e : p.positions) eta.insert(eta.end(), {e(0), e(1), e(2)});
  EXPECT_NEAR(score_positions(eta.data(), 18, CriterionKind::D), 17006112.0, 1e-6);
  EXPECT_NEAR(score_positions(eta.data(), 18, CriterionKind::A), 78.0, 1e-11);
}

TEST(RandomSearchKernel, RankDeficientIsInfinite) {
  std::vector<double> eta(27, 0.0);
  for (int i = 0; i < 9; ++i) eta[static_cast<std::size_t>(3 * i)] = (i % 2) ? 1.0 : -1.0;  // only +-x
  EXPECT_TRUE(std::isinf(score_positions(eta.data(), 9, CriterionKind::D)));
}

TEST(RandomSearch, SameSeedSameResultWithAnyThreadCount) {
  const RandomSearchResult a = random_search(12, 50000, CriterionKind::D, 5, 1);
  const RandomSearchResult b = random_search(12, 50000, CriterionKind::D, 5, 2);
  const RandomSearchResult c = random_search(12, 50000, CriterionKind::D, 5, 3);
  EXPECT_EQ(a.best, b.best);
  EXPECT_EQ(a.best, c.best);
  ASSERT_EQ(a.program.size(), 12);
  EXPECT_EQ(a.program.positions[3], c.program.positions[3]);
  EXPECT_NEAR(evaluate(a.program).D, a.best, 1e-6 * a.best);
  EXPECT_GE(a.best, 61509375.0 / 4.0);
}

}  // namespace
}  // namespace scalcal
