// A new criterion is one file (tests/common/integrated_variance_criterion.hpp): evaluation, random
// search's kernel view, Riemannian Newton, the Ipopt confirmation, the multistart and the MPFR polish
// run on it unchanged. Hand values: for a spherical 4-design M/N = W, so I = tr(I_9) = 9; and since
// h^T W^-1 h = 9 on the whole sphere (the D certificate), the uniform measure is I-optimal: I >= 9.
// classic18 has K = diag(I/6, (I - J/6)/3, I) and W = diag(I/3, (2/15) I + J/15, I/15), so
// I = 18 (3/18 + 13/90 + 3/15) = 46/5.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/polish/polish_form.hpp"
#include "numeric/synthesis/random_search_kernel.hpp"
#include "numeric/synthesis/synthesize.hpp"
#include "tests/common/integrated_variance_criterion.hpp"

namespace scalcal {
namespace {

using testing::IntegratedVarianceCriterion;

TEST(NewCriterion, ValuesByHand) {
  EXPECT_NEAR(criterion_value<IntegratedVarianceCriterion>(Program::classic18()), 46.0 / 5.0, 1e-12);
  EXPECT_NEAR(criterion_value<IntegratedVarianceCriterion>(Program::dodecahedral()), 9.0, 1e-12);
  // The random-search kernel reads K its own way (LDL^T) and must agree.
  const Program p = Program::random(15, 4);
  std::vector<double> eta;
  for (const auto& v : p.positions) eta.insert(eta.end(), {v(0), v(1), v(2)});
  const int np = padded_size(15);
  std::vector<double> x(static_cast<std::size_t>(np), 0.0), y(x), z(x);
  for (int i = 0; i < 15; ++i) x[i] = eta[3 * i], y[i] = eta[3 * i + 1], z[i] = eta[3 * i + 2];
  double m45[45];
  accumulate_information(x.data(), y.data(), z.data(), np, 15, m45);
  EXPECT_NEAR(score_information<IntegratedVarianceCriterion>(m45, 15) / criterion_value<IntegratedVarianceCriterion>(p),
              1.0, 1e-10);
}

TEST(NewCriterion, SynthesisReachesTheBoundAndThePolishConfirmsIt) {
  SynthesisOptions o;
  o.positions = 12;
  o.starts = 4;
  o.threads = 1;
  const SynthesisResult r = synthesize<IntegratedVarianceCriterion>(o);
  EXPECT_EQ(r.local_solver, "newton");  // a smooth form
  EXPECT_TRUE(r.summary.converged()) << r.summary.message;
  EXPECT_NEAR(r.value, 9.0, 1e-9);
  const PolishResult p = polish<IntegratedVarianceCriterion>(r.program, PolishOptions{30, 40});
  ASSERT_TRUE(p.converged()) << p.residual;
  EXPECT_EQ(p.value_digits.substr(0, 31), "9.00000000000000000000000000000");
}

}  // namespace
}  // namespace scalcal
