// The D limit on a cap or band (numeric/region/zonal_d.hpp) against what is derived without it:
// the enclosures proven in exact rational arithmetic by proofs/checks/cap_d_limit.cpp (GiNaC), the
// threshold -(1 + sqrt 6)/5 of the moment problem, the 9 x 9 information matrix of the measure's
// positions computed directly, and the general region machinery.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/region/zonal_d.hpp"
#include "tests/region/cap_d_enclosures.hpp"

namespace scalcal {
namespace {

constexpr double kSphereLimit = 61509375.0 / 4.0;

Zone cap(double deg, Vec3 axis = Vec3(0, 0, 1)) { return Zone{axis.normalized(), 0.0, deg}; }

// D = 1 / det M of a weighted set of positions, from the 9 x 9 matrix itself, in long double (a
// 10-degree cap's M has condition 1e10: its LU in double loses six digits).
double direct_d(const std::vector<Vec3>& positions, const std::vector<double>& weights) {
  using MatL = Eigen::Matrix<long double, 9, 9>;
  MatL M = MatL::Zero();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Eigen::Matrix<long double, 9, 1> h = Paper9Model::row(positions[i]).cast<long double>();
    M += static_cast<long double>(weights[i]) * h * h.transpose();
  }
  return static_cast<double>(1.0L / M.determinant());
}

// The proof's enclosures (lower ends, 30 digits), proofs/cap_d_limit.md step 7.
TEST(ZonalD, CapLimitsMatchTheExactEnclosures) {
  for (const auto& c : testing::kCapDEnclosures) {
    const ZonalMeasure m = zonal_d_limit(cap(c.deg));
    EXPECT_FALSE(m.sphere_limit) << c.deg;
    EXPECT_NEAR(m.value / c.exact, 1.0, 1e-11) << c.deg;
    EXPECT_LE(m.lower_bound, c.exact * (1 + 1e-14)) << c.deg;  // proven: never above the truth
    EXPECT_GT(m.lower_bound, c.exact * (1 - 1e-10)) << c.deg;
    ASSERT_EQ(m.heights.size(), 3u);
    EXPECT_NEAR(m.weights[2], 1.0 / 9.0, 1e-12) << c.deg;  // the pole's weight (proof, step 5)
  }
}

// The value from the block formula equals 1 / det M of the measure's positions (5 per circle).
TEST(ZonalD, BlockFormulaAgreesWithTheNineByNineMatrix) {
  for (double deg : {10.0, 45.0, 90.0, 125.0}) {
    for (const Vec3& axis : {Vec3(0, 0, 1), Vec3(1, 2, -2)}) {
      const Zone z = cap(deg, axis);
      const ZonalMeasure m = zonal_d_limit(z);
      std::vector<Vec3> positions;
      std::vector<double> weights;
      zonal_positions(z, m, positions, weights);
      EXPECT_EQ(positions.size(), 11u);  // rim and circle 5 each, the pole 1
      for (const Vec3& x : positions) EXPECT_TRUE(z.contains(x, 1e-9));
      EXPECT_NEAR(direct_d(positions, weights) / m.value, 1.0, 1e-8) << deg;
    }
  }
}

// The sphere's limit is reached exactly from theta* = arccos(-(1 + sqrt 6)/5) = 133.622 degrees on,
// and on the band |z| <= sqrt(3/5) (Gauss-Legendre's three heights carry the sphere's moments).
TEST(ZonalD, SphereLimitFromTheThresholdOn) {
  const double threshold = std::acos(-(1 + std::sqrt(6.0)) / 5) * 180 / std::numbers::pi;
  const ZonalMeasure below = zonal_d_limit(cap(threshold - 0.01)), above = zonal_d_limit(cap(threshold + 0.01));
  EXPECT_FALSE(below.sphere_limit);
  EXPECT_GT(below.value, kSphereLimit);
  EXPECT_LT(below.value, kSphereLimit * (1 + 1e-5));  // continuous at the threshold
  EXPECT_TRUE(above.sphere_limit);
  EXPECT_EQ(above.value, kSphereLimit);
  std::vector<Vec3> positions;
  std::vector<double> weights;
  zonal_positions(cap(threshold + 0.01), above, positions, weights);
  EXPECT_NEAR(direct_d(positions, weights) / kSphereLimit, 1.0, 1e-12);
  const double edge = std::acos(std::sqrt(0.6)) * 180 / std::numbers::pi;  // 39.23 degrees
  EXPECT_TRUE(zonal_d_limit(Zone{Vec3(0, 0, 1), edge - 0.01, 180 - edge + 0.01}).sphere_limit);
  EXPECT_FALSE(zonal_d_limit(Zone{Vec3(0, 0, 1), edge + 0.5, 180 - edge - 0.5}).sphere_limit);
}

// A band: three circles too (its two rims and one inside). The general machinery (grid measure,
// climbing, interval bound over the band), made to run by a candidate that breaks the band's
// symmetry, must bracket the one-dimensional solution: its bound below, its measure within 1e-3
// above (a measure spread along circles converges slowly on a two-dimensional grid: 1.7e-4 and
// 6e-4 measured with and without extra rings).
TEST(ZonalD, BandAgreesWithTheGeneralMachinery) {
  const Zone band{Vec3(0, 0, 1), 60, 100};
  const ZonalMeasure m = zonal_d_limit(band);
  EXPECT_LE(m.lower_bound, m.value);
  EXPECT_LT((m.value - m.lower_bound) / m.value, 1e-10);
  Region r = parse_region({"band:60:100"});
  r.candidates.push_back(Vec3(std::sin(1.2), 0, std::cos(1.2)));  // not zonal any more: the general path
  const RegionLimit general = region_limit(CriterionKind::D, r);
  EXPECT_GE(general.value, m.lower_bound);
  EXPECT_LT(general.value / m.value, 1 + 1e-3);
  ASSERT_TRUE(general.lower_bound.has_value());
  EXPECT_LE(*general.lower_bound, m.value * (1 + 1e-12));
}

}  // namespace
}  // namespace scalcal
