// Run orders: the plan visits every position once with a setting that measures it, its travel
// (recomputed here from the angles, the short way round on turntables) is never above the given
// order's, and it remounts no more than the fewest mountings need. The positions come from random
// programs inside each bench's reach, 20 seeds each.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "numeric/bench/run_order.hpp"
#include "numeric/program/random_sphere.hpp"

namespace scalcal {
namespace {

// Travel of one axis written out again: a turntable goes the short way round, a limited axis straight.
double travel_here(const Bench& bench, const RunPlan& plan) {
  double t = 0;
  const auto& axes = bench.axes();
  for (std::size_t k = 1; k < plan.steps.size(); ++k)
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const double d = std::abs(plan.steps[k].setting.angles[a] - plan.steps[k - 1].setting.angles[a]);
      t += axes[a].continuous ? std::min(std::fmod(d, 360.0), 360 - std::fmod(d, 360.0)) : d;
    }
  return t;
}

int mounting_changes(const RunPlan& plan) {
  int n = 0;
  for (std::size_t k = 1; k < plan.steps.size(); ++k)
    n += plan.steps[k].setting.mounting != plan.steps[k - 1].setting.mounting;
  return n;
}

// N positions the bench reaches, drawn uniformly on the sphere and kept when reachable.
std::vector<Vec3> reachable_positions(const Bench& bench, int n, std::uint64_t seed) {
  SphereSampler s(seed);
  std::vector<Vec3> out;
  while (static_cast<int>(out.size()) < n)
    if (const Vec3 x = s(); !bench.settings(x).empty()) out.push_back(x);
  return out;
}

TEST(RunOrder, NeverTravelsMoreThanTheGivenOrderAndMeasuresEveryPosition) {
  for (const char* spec :
       {"tilt:40:flip", "gimbal:x,y", "gimbal:y,x:limits=-120..120,-90..90", "faces:30", "gimbal:z,y,x"}) {
    const Bench bench = parse_bench(spec);
    double saved = 0, given_total = 0;
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const std::vector<Vec3> positions = reachable_positions(bench, 18, seed);
      std::vector<std::vector<BenchSetting>> choices;
      for (const Vec3& x : positions) choices.push_back(bench.settings(x));
      const RunPlan given = plan_run(bench, choices, RunOrder::given);
      const RunPlan planned = plan_run(bench, choices, RunOrder::travel);
      std::set<int> seen;
      for (std::size_t k = 0; k < planned.steps.size(); ++k) {
        const RunStep& s = planned.steps[k];
        seen.insert(s.position);
        EXPECT_LT((bench.position(s.setting) - positions[static_cast<std::size_t>(s.position)]).norm(), 1e-12) << spec;
        EXPECT_EQ(given.steps[k].position, static_cast<int>(k)) << spec;
      }
      EXPECT_EQ(seen.size(), positions.size()) << spec;
      EXPECT_NEAR(travel_here(bench, planned), planned.travel_deg, 1e-9) << spec;
      EXPECT_NEAR(travel_here(bench, given), given.travel_deg, 1e-9) << spec;
      EXPECT_LE(planned.remounts, given.remounts) << spec;
      EXPECT_EQ(planned.remounts, mounting_changes(planned)) << spec;
      if (planned.remounts == given.remounts)
        EXPECT_LE(planned.travel_deg, given.travel_deg + 1e-9) << spec << " seed " << seed;
      saved += given.travel_deg - planned.travel_deg;
      given_total += given.travel_deg;
    }
    // A random order of 18 positions travels far more than a good one: the heuristic must find it.
    EXPECT_GT(saved / given_total, 0.3) << spec;
  }
}

// tilt:40:flip with positions in both caps needs exactly one remount; faces:0 with the six axis
// positions five.
TEST(RunOrder, RemountsAreTheFewestMountingsLessOne) {
  const Bench tilt = parse_bench("tilt:40:flip");
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    std::vector<std::vector<BenchSetting>> choices;
    int upper = 0;
    for (const Vec3& x : reachable_positions(tilt, 12, seed)) {
      choices.push_back(tilt.settings(x));
      upper += x.z() > 0;
    }
    const int expected = (upper > 0 && upper < 12) ? 1 : 0;
    EXPECT_EQ(plan_run(tilt, choices, RunOrder::travel).remounts, expected);
    EXPECT_EQ(plan_run(tilt, choices, RunOrder::remounts).remounts, expected);
  }
  const Bench faces = parse_bench("faces");
  std::vector<std::vector<BenchSetting>> axes;
  for (const Vec3& x : std::vector<Vec3>{Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, -1), Vec3(-1, 0, 0), Vec3(0, 0, 1),
                                         Vec3(0, -1, 0), Vec3(1, 0, 0), Vec3(0, 0, -1)})
    axes.push_back(faces.settings(x));
  EXPECT_EQ(plan_run(faces, axes, RunOrder::travel).remounts, 5);
  EXPECT_EQ(plan_run(faces, axes, RunOrder::given).remounts, 7);
}

// --order remounts keeps the given order within each mounting.
TEST(RunOrder, RemountsOrderKeepsTheGivenOrderWithinAMounting) {
  const Bench tilt = parse_bench("tilt:40:flip");
  std::vector<std::vector<BenchSetting>> choices;
  for (const Vec3& x : reachable_positions(tilt, 16, 5)) choices.push_back(tilt.settings(x));
  const RunPlan p = plan_run(tilt, choices, RunOrder::remounts);
  for (std::size_t k = 1; k < p.steps.size(); ++k)
    if (p.steps[k].setting.mounting == p.steps[k - 1].setting.mounting)
      EXPECT_GT(p.steps[k].position, p.steps[k - 1].position);
}

}  // namespace
}  // namespace scalcal
