// Bench kinematics against the stated convention, composed here independently of numeric/bench:
// R = R_A1(theta1) R_A2(theta2) ... (Eigen's AngleAxis, right-handed, degrees), eta = R^T (0, 0, 1);
// a tilt table R = R_y(-t) R_z(-a) M with the mounting M written out by hand below. Every setting a
// bench gives for a position must compose to that position to 1e-12, and a position out of reach
// must get none.
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

Vec3 up_in_meter(const Mat3& R) { return R.transpose() * Vec3(0, 0, 1); }

// The mounting of a tilt table with `up` pointing up (rows: its azimuth frame e1, e2, then up), by
// hand: +z: I; -z: x, -y, -z; +x: y, z, x; -x: y, -z, -x; +y: x, -z, y; -y: x, z, -y.
Mat3 mounting(const Vec3& up) {
  Mat3 M;
  if (up.z() == 1) M << 1, 0, 0, 0, 1, 0, 0, 0, 1;
  if (up.z() == -1) M << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  if (up.x() == 1) M << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  if (up.x() == -1) M << 0, 1, 0, 0, 0, -1, -1, 0, 0;
  if (up.y() == 1) M << 1, 0, 0, 0, 0, -1, 0, 1, 0;
  if (up.y() == -1) M << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  return M;
}

double tilt_from(const Vec3& axis, const Vec3& x) {
  return std::atan2(axis.cross(x).norm(), axis.dot(x)) * 180 / std::numbers::pi;
}

std::vector<Vec3> random_positions(int n, std::uint64_t seed) {
  SphereSampler s(seed);
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i) out.push_back(s());
  return out;
}

TEST(BenchKinematics, GimbalSettingsComposeToThePosition) {
  struct Case {
    const char* spec;
    std::vector<Vec3> axes;
  };
  const Vec3 x = Vec3::UnitX(), y = Vec3::UnitY(), z = Vec3::UnitZ();
  const std::vector<Case> cases = {
      {"gimbal:x,y", {x, y}},      {"gimbal:y,x", {y, x}},
      {"gimbal:-x,z", {-x, z}},    {"gimbal:x,y,x", {x, y, x}},
      {"gimbal:z,y,x", {z, y, x}}, {"gimbal:y,z,x:limits=-90..90,-180..180,-45..45", {y, z, x}}};
  for (const auto& c : cases) {
    const Bench bench = parse_bench(c.spec);
    int reached = 0;
    for (const Vec3& eta : random_positions(300, 7)) {
      const auto settings = bench.settings(eta);
      reached += !settings.empty();
      for (const BenchSetting& s : settings) {
        Mat3 R = Mat3::Identity();
        for (std::size_t k = 0; k < c.axes.size(); ++k)
          R = R * rotation(c.axes[k], std::isnan(s.angles[k]) ? 0 : s.angles[k]);
        EXPECT_LT((up_in_meter(R) - eta).norm(), 1e-12) << c.spec;
        EXPECT_LT((bench.orientation(s) - R).norm(), 1e-12) << c.spec;  // the orientation the bench reports
        for (std::size_t k = 0; k < s.angles.size(); ++k)
          if (!std::isnan(s.angles[k]) && !bench.axes()[k].continuous) {
            EXPECT_GE(s.angles[k], bench.axes()[k].lo) << c.spec;
            EXPECT_LE(s.angles[k], bench.axes()[k].hi) << c.spec;
          }
      }
    }
    // Unlimited x,y-type gimbals and any three-axis one reach every direction; the limited one a part.
    if (std::string(c.spec).find("limits") == std::string::npos)
      EXPECT_EQ(reached, 300) << c.spec;
    else
      EXPECT_GT(reached, 0) << c.spec;
  }
}

// gimbal:z,y: the vertical outer axis turns the meter about the measured vector, so only the inner
// axis tips it: R_y(t2)^T e_z = (-sin t2, 0, cos t2), the x-z great circle.
TEST(BenchKinematics, AVerticalOuterAxisReachesOneGreatCircle) {
  const Bench bench = parse_bench("gimbal:z,y");
  EXPECT_TRUE(bench.settings(Vec3(0, 0.6, 0.8)).empty());
  const Vec3 on(-std::sin(0.3), 0, std::cos(0.3));
  const auto settings = bench.settings(on);
  ASSERT_FALSE(settings.empty());
  for (const auto& s : settings) {
    EXPECT_TRUE(std::isnan(s.angles[0]));  // free
    EXPECT_NEAR(s.angles[1], 0.3 * 180 / std::numbers::pi, 1e-9);
  }
}

TEST(BenchKinematics, TiltTableSettingsComposeToThePositionAndStayWithinTheTilt) {
  for (const char* spec : {"tilt:40", "tilt:40:flip", "faces:10", "faces", "tilt:180"}) {
    const Bench bench = parse_bench(spec);
    const auto& mountings = bench.mountings();
    std::vector<Vec3> ups;
    if (std::string(spec).starts_with("tilt"))
      ups = {Vec3::UnitZ(), -Vec3::UnitZ()};
    else
      ups = {Vec3::UnitZ(), -Vec3::UnitZ(), Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY()};
    const double max_tilt = bench.axes()[0].hi;
    std::vector<Vec3> positions = random_positions(500, 11);
    for (const Vec3& u : ups) positions.push_back(u);  // poles: the azimuth is free
    for (const Vec3& eta : positions) {
      const auto settings = bench.settings(eta);
      bool in_reach = false;
      for (std::size_t m = 0; m < mountings.size(); ++m) in_reach = in_reach || tilt_from(ups[m], eta) <= max_tilt;
      EXPECT_EQ(!settings.empty(), in_reach) << spec;
      for (const BenchSetting& s : settings) {
        const double t = s.angles[0], a = std::isnan(s.angles[1]) ? 0 : s.angles[1];
        const Mat3 R = rotation(Vec3::UnitY(), -t) * rotation(Vec3::UnitZ(), -a) *
                       mounting(ups[static_cast<std::size_t>(s.mounting)]);
        EXPECT_LT((up_in_meter(R) - eta).norm(), 1e-12) << spec;
        EXPECT_LT((bench.orientation(s) - R).norm(), 1e-12) << spec;
        EXPECT_LE(std::abs(t), max_tilt) << spec;
        // The stated meaning: the tilt from the mounting's up axis.
        EXPECT_NEAR(std::abs(t), tilt_from(ups[static_cast<std::size_t>(s.mounting)], eta), 1e-9) << spec;
      }
    }
  }
}

TEST(BenchKinematics, BadSpecsAreRefusedByName) {
  for (const char* spec :
       {"gimbal:x", "gimbal:x,x", "gimbal:x,w", "gimbal:x,y:limits=0..10", "gimbal:x,y:limits=5..1,0..1", "tilt:0",
        "tilt:200", "tilt:40:spin", "faces:-1", "wheel:3", "jig:no-such-jig"}) {
    try {
      parse_bench(spec);
      ADD_FAILURE() << spec << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "--bench") << spec;
      EXPECT_NE(std::string(e.what()).find(spec), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace scalcal
