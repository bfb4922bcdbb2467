// Region limits in worker processes (numeric/region/region_limits.hpp) against region_limit() called
// one by one in this process: every field the same, bit for bit, whatever worker computed it.
#include <gtest/gtest.h>

#include <vector>

#include "numeric/region/region.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/region/region_limits.hpp"

namespace scalcal {
namespace {

void expect_same(const RegionLimit& a, const RegionLimit& b) {
  EXPECT_EQ(a.value, b.value);
  EXPECT_EQ(a.lower_bound, b.lower_bound);
  EXPECT_EQ(a.K, b.K);
  EXPECT_EQ(a.support, b.support);
  EXPECT_EQ(a.weights, b.weights);
  EXPECT_EQ(a.equivalence_gap, b.equivalence_gap);
  EXPECT_EQ(a.candidates, b.candidates);
  EXPECT_EQ(a.refinements, b.refinements);
  EXPECT_EQ(a.boxes, b.boxes);
  EXPECT_EQ(a.theorem, b.theorem);
}

TEST(RegionLimits, WorkersGiveWhatOneByOneGives) {
  RegionLimitOptions options;
  options.certify = false;  // as fig12 runs them
  options.max_refinements = 3;
  std::vector<RegionLimitTask> tasks;
  for (const char* spec : {"cap:60", "faces:20"})
    for (auto c : kCriteria) tasks.push_back({c, parse_region({spec})});
  int last = 0;
  const std::vector<RegionLimit> together = region_limits(tasks, options, 2, [&](int done, int total) {
    EXPECT_EQ(total, static_cast<int>(tasks.size()));
    EXPECT_GT(done, last);
    last = done;
  });
  ASSERT_EQ(together.size(), tasks.size());
  EXPECT_EQ(last, static_cast<int>(tasks.size()));
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    SCOPED_TRACE(criterion_name(tasks[k].criterion));
    expect_same(together[k], region_limit(tasks[k].criterion, tasks[k].region, options));
    EXPECT_FALSE(together[k].support.empty());
  }
}

TEST(RegionLimits, ProvenBoundsCrossThePipeToo) {
  // D on a band is one-dimensional (zonal_d.hpp), with its proven bound: the cheap certified case (on a
  // cap D is a theorem's closed form, computed in this process).
  const std::vector<RegionLimitTask> tasks{{CriterionKind::D, parse_region({"band:20:60:1,0,1"})},
                                           {CriterionKind::D, parse_region({"band:45:135"})}};
  const std::vector<RegionLimit> together = region_limits(tasks, {}, 2);
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    ASSERT_TRUE(together[k].lower_bound.has_value());
    EXPECT_EQ(status_of(together[k]), LimitStatus::certified);
    expect_same(together[k], region_limit(tasks[k].criterion, tasks[k].region));
  }
}

}  // namespace
}  // namespace scalcal
