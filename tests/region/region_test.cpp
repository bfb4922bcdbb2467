// Regions: spec parsing, membership, and the limits over a region against values derived
// independently (the proven sphere limits, a jig evaluated by the SVD path, hand geometry).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>

#include <gtest/gtest.h>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/program/program_csv.hpp"
#include "numeric/region/region.hpp"
#include "numeric/region/region_limit.hpp"

namespace scalcal {
namespace {

Vec3 at_tilt(double tilt_deg, double azimuth_deg) {
  const double t = tilt_deg * std::numbers::pi / 180, a = azimuth_deg * std::numbers::pi / 180;
  return Vec3(std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t));
}

TEST(RegionSpec, CapAboutZAndAboutAGivenAxis) {
  const Region cap = parse_region({"cap:30"});
  EXPECT_TRUE(cap.contains(at_tilt(29.9, 123)));
  EXPECT_TRUE(cap.contains(at_tilt(30.0, 7)));  // the rim belongs to the cap
  EXPECT_FALSE(cap.contains(at_tilt(30.1, 7)));
  const Region x = parse_region({"cap:10:2,0,0"});  // the axis is normalised
  EXPECT_TRUE(x.contains(Vec3(1, 0, 0)));
  EXPECT_TRUE(x.contains(Vec3(std::cos(0.17), std::sin(0.17), 0)));   // 9.74 degrees
  EXPECT_FALSE(x.contains(Vec3(std::cos(0.18), std::sin(0.18), 0)));  // 10.31 degrees
}

// Issue 36 item 4: an axis of subnormal components was divided by its subnormal norm, which keeps
// a few bits, and the cap about "1e-323,0,1e-323" was not the cap about (1,0,1) (A's proven bound
// 30485.5 instead of 1825429.6). Both parse to (1,0,1)/sqrt(2) to rounding, as does 1e300,0,1e300.
TEST(RegionSpec, AxisOfAnyScaleIsTheSameDirection) {
  const Vec3 expected = Vec3(1, 0, 1) / std::sqrt(2.0);
  for (const char* spec :
       {"cap:30:1e-323,0,1e-323", "cap:30:1,0,1", "cap:30:1e300,0,1e300", "cap:30:5e-324,0,5e-324"}) {
    const Region r = parse_region({spec});
    ASSERT_EQ(r.zones.size(), 1u) << spec;
    EXPECT_LE((r.zones[0].axis - expected).norm(), 2e-16) << spec;
  }
}

TEST(RegionSpec, BandFacesAndUnion) {
  const Region band = parse_region({"band:60:120"});
  EXPECT_TRUE(band.contains(at_tilt(90, 45)));
  EXPECT_FALSE(band.contains(at_tilt(59, 45)));
  EXPECT_FALSE(band.contains(at_tilt(121, 45)));
  const Region faces = parse_region({"faces:15"});
  EXPECT_EQ(faces.zones.size(), 6u);
  for (const Vec3& axis : {Vec3(1, 0, 0), Vec3(0, -1, 0), Vec3(0, 0, -1)}) EXPECT_TRUE(faces.contains(axis));
  EXPECT_FALSE(faces.contains(Vec3(1, 1, 1).normalized()));  // 54.7 degrees from every axis
  const Region both = parse_region({"cap:10", "cap:10:0,0,-1"});
  EXPECT_TRUE(both.contains(Vec3(0, 0, -1)));
  EXPECT_EQ(both.text(), "cap:10 + cap:10:0,0,-1");
  EXPECT_TRUE(parse_region({}).is_sphere());
}

TEST(RegionSpec, GridStaysInsideAndCoversTheRim) {
  const Region cap = parse_region({"cap:30:1,1,0"});
  const auto grid = cap.grid(3.0);
  double widest = 0;
  for (const Vec3& x : grid) {
    EXPECT_NEAR(x.norm(), 1.0, 1e-12);
    EXPECT_TRUE(cap.contains(x, 1e-9));
    widest = std::max(widest, cap.zones[0].tilt_deg(x));
  }
  EXPECT_NEAR(widest, 30.0, 1e-9);
}

TEST(RegionSpec, BadSpecsAreInputErrors) {
  for (const char* spec : {"",
                           "cap",
                           "cap:",
                           "cap:0",
                           "cap:181",
                           "cap:-5",
                           "cap:30:1,0",
                           "cap:30:0,0,0",
                           "cap:x",
                           "cap:30:1,0,0:9",
                           "band:50",
                           "band:60:60",
                           "band:70:60",
                           "band:10:200",
                           "faces",
                           "faces:0",
                           "faces:10:20",
                           "sphere:5",
                           "torus:3",
                           "candidates:",
                           "candidates:/nonexistent/file.csv",
                           "cap:nan",
                           "cap:1e400"}) {
    EXPECT_THROW(parse_region({spec}), InputError) << spec;
  }
}

TEST(RegionSpec, CandidatesOnOneGreatCircleCannotGiveRankNine) {
  const std::string path = testing::TempDir() + "equator.csv";
  {
    std::ofstream f(path);
    f << "x,y,z\n";
    for (int k = 0; k < 12; ++k) f << std::cos(k * 0.5) << "," << std::sin(k * 0.5) << ",0\n";
  }
  const Region r = parse_region({"candidates:" + path});
  EXPECT_EQ(r.candidates.size(), 12u);
  EXPECT_THROW(check_region_identifiable(r), InputError);
  std::remove(path.c_str());
}

// The sphere's limits are proven in closed form (proofs/): the certified bound may not exceed them
// and the measure found may not go below them. The sphere's optimum fits on the sphere, so the
// bound is the proven limit itself and the gap is only the measure's distance from optimal
// (measured: below 1e-9 for D and A, 3e-6 for the smoothed E and S on the grid).
TEST(RegionLimit, SphereBracketsTheProvenLimits) {
  const Region sphere = parse_region({"sphere"});
  for (auto c : kCriteria) {
    const double exact = criterion_limit(c).value;
    const RegionLimit l = region_limit(c, sphere);
    ASSERT_TRUE(l.lower_bound.has_value()) << criterion_name(c);
    EXPECT_LE(*l.lower_bound, exact * (1 + 1e-12)) << criterion_name(c);
    EXPECT_GE(l.value, exact * (1 - 1e-12)) << criterion_name(c);
    EXPECT_LT((l.value - *l.lower_bound) / exact, 1e-5) << criterion_name(c);
    EXPECT_LT((l.value - exact) / exact, 1e-4) << criterion_name(c);  // the measure itself is near optimal
    double total = 0;
    for (double w : l.weights) total += w;
    EXPECT_NEAR(total, 1.0, 1e-3) << criterion_name(c);
  }
}

// The dodecahedral jig's twelve directions as the only candidates: the jig itself is D-optimal on
// them (its symmetry group is transitive on them and D is rotation-invariant), so the limit there
// is the jig's N^9 det K at N = 12, computed by the SVD of its H.
TEST(RegionLimit, DodecahedralCandidatesGiveTheJigsValue) {
  const Program jig = resolve_program("dodecahedral-12");
  const std::string path = testing::TempDir() + "dodecahedral.csv";
  ASSERT_TRUE(write_program_csv(path, jig));
  const Region r = parse_region({"candidates:" + path});
  const RegionLimit l = region_limit(CriterionKind::D, r);
  const double jig_value = evaluate(jig).value(CriterionKind::D);
  EXPECT_NEAR(l.value / jig_value, 1.0, 1e-9);
  ASSERT_TRUE(l.lower_bound.has_value());
  EXPECT_LE(*l.lower_bound, jig_value * (1 + 1e-12));
  EXPECT_NEAR(*l.lower_bound / jig_value, 1.0, 1e-6);
  EXPECT_EQ(l.support.size(), 12u);
  for (double w : l.weights) EXPECT_NEAR(w, 1.0 / 12, 1e-6);
  std::remove(path.c_str());
}

// Every support position lies in the region, and restricting the region never helps.
TEST(RegionLimit, CapSupportInsideAndWorseThanTheSphere) {
  const Region cap = parse_region({"cap:60:1,0,1"});
  for (auto c : kCriteria) {
    const RegionLimit l = region_limit(c, cap);
    for (const Vec3& x : l.support) EXPECT_TRUE(cap.contains(x, 1e-6)) << criterion_name(c);
    EXPECT_GT(l.value, criterion_limit(c).value) << criterion_name(c);
    ASSERT_TRUE(l.lower_bound.has_value());
    EXPECT_LE(*l.lower_bound, l.value) << criterion_name(c);
    EXPECT_GT(*l.lower_bound, criterion_limit(c).value) << criterion_name(c);
  }
}

}  // namespace
}  // namespace scalcal
