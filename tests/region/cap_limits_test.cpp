// The closed forms of a cap's limits (numeric/region/cap_limits.hpp) against what is derived without
// them: the enclosures proven in exact arithmetic by proofs/checks/cap_d_limit.cpp, the values
// proofs/cap_es_limits.md states, the thresholds' defining polynomials, the criteria of the measure's
// positions computed from the 9 x 9 matrix, and, so that no theorem's label can stand on a wrong
// value, the region solver's certified enclosure (its proven lower bound never above the closed form).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "numeric/model/paper9.hpp"
#include "numeric/region/cap_limits.hpp"
#include "numeric/region/region_limit.hpp"
#include "tests/region/cap_d_enclosures.hpp"

namespace scalcal {
namespace {

Region cap(double deg, const char* axis = nullptr) {
  return parse_region({"cap:" + std::to_string(deg) + (axis ? std::string(":") + axis : std::string())});
}

// K of the closed form's measure, from the 9 x 9 information matrix of its positions (long double).
Mat9 measure_k(const RegionLimit& l) {
  using MatL = Eigen::Matrix<long double, 9, 9>;
  MatL M = MatL::Zero();
  for (std::size_t i = 0; i < l.support.size(); ++i) {
    const Eigen::Matrix<long double, 9, 1> h = Paper9Model::row(l.support[i]).cast<long double>();
    M += static_cast<long double>(l.weights[i]) * h * h.transpose();
  }
  return M.inverse().cast<double>();
}

TEST(CapLimits, ThresholdsSolveTheirPolynomials) {
  const long double c = kCapDSphereCosine, s = kCapSThreshold, e = kCapEThreshold;
  EXPECT_LT(std::abs(5 * c * c + 2 * c - 1), 1e-17L);  // 5c^2 + 2c - 1 = 5 (c - c*)(c - (sqrt 6 - 1)/5)
  EXPECT_LT(c, -0.5L);
  EXPECT_LT(std::abs(s * s + 6 * s + 1), 1e-17L);  // c^2 + 6c + 1 vanishes at -3 + 2 sqrt 2
  EXPECT_GT(s, -1.0L);
  const auto p7 = [](long double x) {
    return ((((((9 * x + 231) * x + 1973) * x + 7275) * x + 14459) * x + 16181) * x + 9287) * x + 1785;
  };
  EXPECT_LT(p7(e - 1e-15L), 0);  // the root in (-0.35, -0.348] (proofs/cap_es_limits.md step 4)
  EXPECT_GT(p7(e + 1e-15L), 0);
}

// proofs/cap_d_limit.md step 7: enclosures of relative width 1.8e-44 (lower ends shown).
TEST(CapLimits, DMatchesTheProvenEnclosures) {
  for (const auto& c : testing::kCapDEnclosures) {
    const auto f = cap_closed_form(CriterionKind::D, cap(c.deg));
    ASSERT_TRUE(f) << c.deg;
    EXPECT_EQ(f->theorem, "proofs/cap_d_limit.md");
    EXPECT_FALSE(f->sphere_limit);
    EXPECT_NEAR(f->value / c.exact, 1.0, 1e-15) << c.deg;
    EXPECT_DOUBLE_EQ(f->weights[0], 1.0 / 9.0);  // the pole
  }
  const auto beyond = cap_closed_form(CriterionKind::D, cap(140));
  ASSERT_TRUE(beyond);
  EXPECT_TRUE(beyond->sphere_limit);
  EXPECT_EQ(beyond->value, 61509375.0 / 4.0);
}

// proofs/cap_es_limits.md: the hemisphere's 147 and 81, the 60-degree cap's 5283 and 2401.
TEST(CapLimits, EAndSMatchTheTheorem) {
  for (const auto& [deg, e, s] : {std::tuple{90.0, 147.0, 81.0}, std::tuple{60.0, 5283.0, 2401.0}}) {
    const auto fe = cap_closed_form(CriterionKind::E, cap(deg)), fs = cap_closed_form(CriterionKind::S, cap(deg));
    ASSERT_TRUE(fe && fs) << deg;
    EXPECT_NEAR(fe->value, e, e * 1e-15);
    EXPECT_NEAR(fs->value, s, s * 1e-15);
    EXPECT_EQ(fe->theorem, "proofs/cap_es_limits.md");
  }
  // About another coordinate axis (E and S are invariant under the signed permutations), not about a tilted one.
  EXPECT_TRUE(cap_closed_form(CriterionKind::E, cap(60, "-1,0,0")));
  EXPECT_TRUE(cap_closed_form(CriterionKind::S, cap(60, "0,2,0")));
  EXPECT_FALSE(cap_closed_form(CriterionKind::E, cap(60, "1,1,0")));
  EXPECT_TRUE(cap_closed_form(CriterionKind::D, cap(60, "1,1,0")));  // D: any axis
  // The proven half-angles: E up to 110.3755, S up to 99.8793 degrees.
  EXPECT_TRUE(cap_closed_form(CriterionKind::E, cap(110.37)));
  EXPECT_FALSE(cap_closed_form(CriterionKind::E, cap(110.38)));
  EXPECT_TRUE(cap_closed_form(CriterionKind::S, cap(99.87)));
  EXPECT_FALSE(cap_closed_form(CriterionKind::S, cap(99.88)));
  EXPECT_FALSE(cap_closed_form(CriterionKind::A, cap(90)));
  EXPECT_FALSE(cap_closed_form(CriterionKind::D, parse_region({"band:30:90"})));
  EXPECT_FALSE(cap_closed_form(CriterionKind::D, parse_region({"faces:30"})));
  EXPECT_FALSE(cap_closed_form(CriterionKind::D, parse_region({"cap:30", "cap:30:0,0,-1"})));
}

// The measure the closed form names has that criterion value, from its own 9 x 9 matrix.
TEST(CapLimits, TheMeasureHasTheValue) {
  for (double deg : {30.0, 60.0, 90.0, 110.0, 120.0, 150.0})
    for (auto c : {CriterionKind::D, CriterionKind::E, CriterionKind::S}) {
      const Region region = cap(deg, "0,0,-1");
      if (!cap_closed_form(c, region)) continue;
      const RegionLimit l = region_limit(c, region);
      EXPECT_EQ(status_of(l), LimitStatus::proven);
      for (const Vec3& x : l.support) EXPECT_TRUE(region.contains(x, 1e-9));
      const Mat9 K = measure_k(l);
      const double value = c == CriterionKind::D   ? 1.0 / K.inverse().determinant()
                           : c == CriterionKind::E ? Eigen::SelfAdjointEigenSolver<Mat9>(K).eigenvalues().maxCoeff()
                                                   : K.diagonal().maxCoeff();
      EXPECT_NEAR(value / l.value, 1.0, deg < 45 ? 1e-7 : 1e-10) << criterion_name(c) << " " << deg;
    }
}

// A theorem's label must never stand on a value the certified solver contradicts: its proven lower
// bound is at most the closed form (to the long double evaluation's 1e-15), and its optimal measure is
// at or above it (to the measure's double evaluation).
TEST(CapLimits, CertifiedEnclosuresContainTheClosedForms) {
  RegionLimitOptions solver;
  solver.closed_forms = false;
  // D (one-dimensional, cheap) on two caps, E and S (the grid solver, 1-2 s each) on the hemisphere.
  for (const auto& [c, deg] : {std::pair{CriterionKind::D, 60.0}, std::pair{CriterionKind::D, 90.0},
                               std::pair{CriterionKind::E, 90.0}, std::pair{CriterionKind::S, 90.0}}) {
    const Region region = cap(deg);
    const auto f = cap_closed_form(c, region);
    ASSERT_TRUE(f);
    const RegionLimit l = region_limit(c, region, solver);
    ASSERT_TRUE(l.lower_bound) << criterion_name(c) << " " << deg;
    EXPECT_EQ(status_of(l), LimitStatus::certified);
    EXPECT_LE(*l.lower_bound, f->value * (1 + 1e-15)) << criterion_name(c) << " " << deg;
    EXPECT_GE(l.value, f->value * (1 - 1e-10)) << criterion_name(c) << " " << deg;
    EXPECT_LT(l.value, f->value * (1 + 1e-6)) << criterion_name(c) << " " << deg;
  }
}

TEST(CapLimits, SphereAndRegionStatements) {
  const LimitStatement sphere = limit_statement(CriterionKind::A, sphere_region());
  EXPECT_EQ(sphere.status, LimitStatus::proven);
  EXPECT_EQ(sphere.theorem, "proofs/aes_limits.md");
  const LimitStatement e = limit_statement(CriterionKind::E, cap(90));
  EXPECT_EQ(e.status, LimitStatus::proven);
  EXPECT_NEAR(e.value, 147.0, 1e-12);
  EXPECT_EQ(limit_statement(CriterionKind::D, parse_region({"band:60:120"})).status, LimitStatus::certified);
  EXPECT_EQ(status_name(LimitStatus::numerical), "numerical");
}

}  // namespace
}  // namespace scalcal
