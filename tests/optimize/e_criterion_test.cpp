// The E multistart against independent facts: the 12 edge positions have, by hand, moments
// a = 1/6, b = 1/12 and so N lambda_max K = 1/min(1/3, a - b, b) = 12, which is also the limit
// (numeric/limits.hpp, proved in proofs/aes_limits.md): the N = 12 optimum must be exactly 12.
// At N = 9 the E optimum can be no worse than the E value of the A-optimal program.
#include <gtest/gtest.h>

#include "numeric/evaluation.hpp"
#include "numeric/synthesis.hpp"

namespace scalcal {
namespace {

SynthesisResult run(int n, CriterionKind c, int starts) {
  SynthesisOptions o;
  o.positions = n;
  o.criterion = c;
  o.starts = starts;
  o.seed = 5;
  return synthesize(o);
}

TEST(ECriterion, ReachesTheEdgeProgramsValueAtTwelve) {
  EXPECT_NEAR(evaluate(Program::octahedral(0, 1, 0)).E, 12.0, 1e-12);
  const SynthesisResult r = run(12, CriterionKind::E, 4);
  EXPECT_NEAR(r.value, 12.0, 1e-6);
  EXPECT_NEAR(evaluate(r.program).E, r.value, 1e-9);
}

TEST(ECriterion, AtNineNoWorseThanTheAOptimum) {
  const SynthesisResult a = run(9, CriterionKind::A, 4);
  const SynthesisResult e = run(9, CriterionKind::E, 4);
  EXPECT_LE(e.value, evaluate(a.program).E + 1e-9);
  EXPECT_GE(e.value, 12.0);
  EXPECT_GT(evaluate(e.program).E, 0.0);
}

}  // namespace
}  // namespace scalcal
