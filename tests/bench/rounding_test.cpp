// Rounding to a bench's resolution never leaves the region: positions designed on a cap's rim (the
// optimum puts most of them there) and at random inside it, rounded to 0.05..5 degrees, are all
// inside by the tilt computed here, every angle a multiple of the resolution and within the bench's
// limits. Rounding each angle to the nearest multiple alone leaves the region for some of them
// (checked, so the test does not pass for want of hard cases).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "numeric/bench/rounding.hpp"
#include "numeric/program/random_sphere.hpp"

namespace scalcal {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

double tilt_from(const Vec3& axis, const Vec3& x) { return std::atan2(axis.cross(x).norm(), axis.dot(x)) / kDeg; }

// Positions on the rim of the cap about `axis` (tilt exactly max_tilt) and uniformly inside it.
std::vector<Vec3> cap_positions(const Vec3& axis, double max_tilt, std::uint64_t seed) {
  SphereSampler s(seed);
  const Vec3 e1 = (std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(axis).normalized(),
             e2 = axis.cross(e1);
  std::vector<Vec3> out;
  for (int i = 0; i < 40; ++i) {
    const double a = 2 * std::numbers::pi * s.uniform();
    const double t = (i % 2 ? max_tilt : max_tilt * std::sqrt(s.uniform())) * kDeg;
    out.push_back(std::cos(t) * axis + std::sin(t) * (std::cos(a) * e1 + std::sin(a) * e2));
  }
  return out;
}

TEST(Rounding, NeverLeavesTheRegion) {
  struct Case {
    const char* bench;
    std::vector<std::string> region;
    Vec3 axis;
    double max_tilt;
  };
  const std::vector<Case> cases = {{"tilt:40:flip", {"cap:40", "cap:40:0,0,-1"}, Vec3(0, 0, -1), 40},
                                   {"tilt:40", {"cap:40"}, Vec3(0, 0, 1), 40},
                                   {"gimbal:x,y", {"cap:40"}, Vec3(0, 0, 1), 40},
                                   {"gimbal:y,x,z", {"cap:25:1,0,0"}, Vec3(1, 0, 0), 25},
                                   {"faces:15", {"faces:15"}, Vec3(0, 1, 0), 15}};
  int naive_outside = 0, rounded = 0;
  for (const auto& c : cases) {
    const Bench bench = parse_bench(c.bench);
    const Region region = parse_region(c.region);
    for (const double resolution : {0.05, 0.1, 0.5, 1.0, 5.0})
      for (const Vec3& eta : cap_positions(c.axis, c.max_tilt, 3)) {
        for (const BenchSetting& s : bench.settings(eta)) {
          BenchSetting exact = s;
          for (double& a : exact.angles)
            if (std::isnan(a)) a = 0;
          const auto r = round_setting(bench, exact, resolution, region);
          ASSERT_TRUE(r.has_value()) << c.bench << " at " << resolution;
          ++rounded;
          const Vec3 x = bench.position(*r);
          EXPECT_LE(tilt_from(c.axis, x), c.max_tilt + 1e-9) << c.bench << " at " << resolution;
          for (std::size_t k = 0; k < r->angles.size(); ++k) {
            const double steps = r->angles[k] / resolution;
            EXPECT_NEAR(steps, std::round(steps), 1e-9);
            if (!bench.axes()[k].continuous) {
              EXPECT_GE(r->angles[k], bench.axes()[k].lo - 1e-12);
              EXPECT_LE(r->angles[k], bench.axes()[k].hi + 1e-12);
            }
          }
          // Within a step of the design on each axis: a rounding, not a new position.
          EXPECT_LT(std::acos(std::clamp(x.dot(eta), -1.0, 1.0)) / kDeg, 3 * resolution * (1 + bench.axes().size()));
          BenchSetting naive = exact;
          for (double& a : naive.angles) a = std::round(a / resolution) * resolution;
          naive_outside += tilt_from(c.axis, bench.position(naive)) > c.max_tilt + 1e-9;
        }
      }
  }
  EXPECT_GT(rounded, 1000);
  EXPECT_GT(naive_outside, 50);
}

}  // namespace
}  // namespace scalcal
