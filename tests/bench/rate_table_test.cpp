// The rate-table bench (numeric/bench/rate_table.hpp) against its statement, composed here by hand:
// the fixture is a tilt table, R = R_y(-t) R_z(-a) (upright mounting), the table's axis is the lab's
// up, so a counterclockwise turn (rate > 0) measures R^T (0, 0, 1) and a clockwise one its antipode.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "numeric/bench/registry.hpp"
#include "numeric/program/random_sphere.hpp"

namespace scalcal {
namespace {

Mat3 rotation(const Vec3& axis, double deg) {
  return Eigen::AngleAxisd(deg * std::numbers::pi / 180, axis).toRotationMatrix();
}

TEST(RateTableBench, EachSettingTurnsTheTableAboutThePositionOrItsAntipode) {
  const Bench bench = parse_bench("rate:40:30:12");
  EXPECT_EQ(bench.text(), "rate:40:30:12");
  SphereSampler sample(3);
  int reached = 0, unreached = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec3 eta = sample();
    const double tilt = std::atan2(std::hypot(eta.x(), eta.y()), std::abs(eta.z())) * 180 / std::numbers::pi;
    const auto settings = bench.settings(eta);
    if (tilt > 40 + 1e-9) {
      EXPECT_TRUE(settings.empty());
      ++unreached;
      continue;
    }
    ASSERT_FALSE(settings.empty());
    ++reached;
    for (const auto& s : settings) {
      ASSERT_EQ(s.angles.size(), 4u);
      const double a = std::isnan(s.angles[1]) ? 0.0 : s.angles[1];
      const Mat3 R = rotation(Vec3::UnitY(), -s.angles[0]) * rotation(Vec3::UnitZ(), -a);
      const double sense = s.angles[2] > 0 ? 1 : -1;
      EXPECT_EQ(std::abs(s.angles[2]), 30);
      EXPECT_EQ(s.angles[3], 12);
      EXPECT_LT((sense * (R.transpose() * Vec3::UnitZ()) - eta).norm(), 1e-12);
      EXPECT_LT((bench.position(s) - eta).norm(), 1e-12);
      // The table upside down: a clockwise setting's z is the meter turned below the horizon.
      EXPECT_EQ(sense > 0, eta.z() > 0);
    }
  }
  EXPECT_GT(reached, 0);
  EXPECT_GT(unreached, 0);
}

TEST(RateTableBench, ReversingTheTableIsNoRemountAndNoTravel) {
  const Bench bench = parse_bench("rate:40:30:12:flip");
  const BenchSetting ccw{0, {20, 10, 30, 12}}, cw{0, {20, 10, -30, 12}};
  EXPECT_FALSE(bench.remount(ccw, cw));
  EXPECT_EQ(bench.travel(ccw, cw), 0);
  EXPECT_LT((bench.position(ccw) + bench.position(cw)).norm(), 1e-15);
}

TEST(RateTableBench, RefusesWhatAnAxisCannotHold) {
  EXPECT_THROW(parse_bench("rate:40:200:10"), InputError);
  EXPECT_THROW(parse_bench("rate:40:30:0"), InputError);
  EXPECT_THROW(parse_bench("rate:40:30"), InputError);
  EXPECT_THROW(parse_bench("rate:40:30:10:upside"), InputError);
}

}  // namespace
}  // namespace scalcal
