// Starts that need no Ipopt run in threads (numeric/synthesis/workers.hpp): the result depends on
// the seed only, not on the number of threads, as it did with worker processes.
#include <gtest/gtest.h>

#include <stdexcept>

#include "numeric/synthesis/multistart.hpp"
#include "numeric/synthesis/workers.hpp"

namespace scalcal {
namespace {

TEST(Threads, SynthesisDoesNotDependOnTheThreadCount) {
  for (CriterionKind c : {CriterionKind::D, CriterionKind::A})
    for (int n : {13, 45}) {  // Newton, then L-BFGS starts
      SynthesisOptions o;
      o.positions = n;
      o.criterion = c;
      o.starts = 12;
      o.seed = 5;
      o.threads = 1;
      const SynthesisResult one = synthesize(o);
      o.threads = 3;
      const SynthesisResult three = synthesize(o);
      EXPECT_EQ(one.value, three.value) << n;
      EXPECT_EQ(one.program.positions, three.program.positions) << n;
      EXPECT_EQ(one.hits, three.hits);
      EXPECT_TRUE(one.summary.converged()) << one.summary.message;
    }
}

TEST(Threads, ResultsByIndexAndExceptionsPassedOn) {
  const std::vector<LocalResult> r = run_in_threads(7, 3, [](int k) {
    LocalResult out;
    out.value = k * k;
    return out;
  });
  ASSERT_EQ(r.size(), 7u);
  for (int k = 0; k < 7; ++k) EXPECT_EQ(r[static_cast<std::size_t>(k)].value, k * k);
  EXPECT_THROW(run_in_threads(5, 2,
                              [](int k) -> LocalResult {
                                if (k == 3) throw std::runtime_error("start 3");
                                return {};
                              }),
               std::runtime_error);
}

}  // namespace
}  // namespace scalcal
