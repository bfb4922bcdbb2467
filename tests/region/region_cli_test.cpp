// --region on the commands as a user runs them: the JSON keys the issue fixes (optimize: region,
// limit, efficiency), what stands behind each limit (status, theorem, exact), the tilt/azimuth columns
// of --out for a cap, and the refusals.
#include <algorithm>
#include <cmath>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using Json = nlohmann::json;

TEST(RegionCli, OptimizeOnACapReportsLimitAndEfficiency) {
  const std::string out = (scratch_dir() / "cap_program.csv").string();
  const auto r = run_cli("optimize --positions 24 --criterion D --region cap:90 --starts 2 --json --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  for (const char* key :
       {"criterion", "positions", "value", "program", "starts", "hits", "distinct", "region", "limit", "efficiency"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["region"], "cap:90");
  // The hemisphere's proven D limit (proofs/cap_d_limit.md).
  EXPECT_NEAR(j["limit"].get<double>() / 9.39809328436720974e8, 1.0, 1e-10);
  const double efficiency = j["efficiency"];
  EXPECT_NEAR(efficiency, std::pow(j["limit"].get<double>() / j["value"].get<double>(), 1.0 / 9), 1e-12);
  EXPECT_GT(efficiency, 0.99);
  EXPECT_LE(efficiency, 1.0 + 1e-12);
  EXPECT_EQ(j["limit_statement"]["status"], "proven");
  EXPECT_EQ(j["limit_statement"]["theorem"], "proofs/cap_d_limit.md");
  // --out for a cap writes the region line, then adds tilt_deg and azimuth_deg; every tilt is within the cap.
  std::istringstream csv(slurp(out));
  std::string region_line, header, line;
  std::getline(csv, region_line);
  EXPECT_EQ(region_line, "# region: cap:90");
  std::getline(csv, header);
  EXPECT_EQ(header, "x,y,z,alpha1_deg,alpha2_deg,tilt_deg,azimuth_deg");
  int rows = 0;
  while (std::getline(csv, line)) {
    double v[7];
    char comma;
    std::istringstream fields(line);
    fields >> v[0];
    for (int k = 1; k < 7; ++k) fields >> comma >> v[k];
    EXPECT_LE(v[5], 90.0 + 1e-6) << line;
    EXPECT_NEAR(std::acos(std::clamp(v[2], -1.0, 1.0)) * 180 / M_PI, v[5], 1e-6) << line;  // tilt from +z
    // One azimuth range per file: -180..180 as alpha1. About +z the azimuth frame is (+x, +y), so
    // away from the pole the azimuth is alpha1 itself (up to the wrap at 180).
    EXPECT_GE(v[6], -180.0);
    EXPECT_LE(v[6], 180.0);
    if (v[5] > 1e-6) EXPECT_NEAR(std::remainder(v[6] - v[3], 360.0), 0.0, 1e-9) << line;
    ++rows;
  }
  EXPECT_EQ(rows, 24);
  // The written program reads back and lies in the region.
  const auto e = run_cli("evaluate " + out + " --region cap:90 --json");
  ASSERT_EQ(e.status, 0) << e.err;
  // evaluate states the limits it judges against as limits does.
  const Json limits = Json::parse(e.out)["limits"];
  EXPECT_EQ(limits["E"]["exact"], "147");
  EXPECT_EQ(limits["E"]["status"], "proven");
  EXPECT_EQ(limits["A"]["status"], "certified");
}

TEST(RegionCli, DigitsCannotKeepPositionsInsideARegion) {
  const auto r = run_cli("optimize --positions 12 --criterion D --region cap:60 --digits 30");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--digits"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(RegionCli, LimitsJsonOnACap) {
  const auto r = run_cli("limits --region cap:60 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["region"], "cap:60");
  for (const char* c : {"D", "A", "E", "S"}) {
    ASSERT_TRUE(j.contains(c)) << c;
    for (const char* key :
         {"value", "lower_bound", "relative_to_sphere", "support", "candidates", "refinements", "equivalence_gap"})
      EXPECT_TRUE(j[c].contains(key)) << c << " " << key;
    EXPECT_LE(j[c]["lower_bound"].get<double>(), j[c]["value"].get<double>()) << c;
    double total = 0;  // the support lists weights of at least 1e-6: the rest is spread thinly
    for (const auto& s : j[c]["support"]) total += s["weight"].get<double>();
    EXPECT_LE(total, 1.0 + 1e-12) << c;
    EXPECT_GT(total, 1.0 - 1e-4) << c;
  }
  EXPECT_NEAR(j["D"]["value"].get<double>() / 2.10863441696092520e13, 1.0, 1e-10);
}

// The "done when": the hemisphere's E and S exactly, with their theorem; D proven; A certified (its
// value an optimal measure's, its bound proven, no exact form); the sphere's limits proven too.
TEST(RegionCli, LimitsStateTheTheoremsOnTheHemisphere) {
  const auto r = run_cli("limits --region cap:90 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["E"]["exact"], "147");
  EXPECT_EQ(j["E"]["theorem"], "proofs/cap_es_limits.md");
  EXPECT_EQ(j["S"]["exact"], "81");
  EXPECT_EQ(j["S"]["theorem"], "proofs/cap_es_limits.md");
  EXPECT_EQ(j["E"]["value"].get<double>(), 147.0);
  EXPECT_EQ(j["S"]["value"].get<double>(), 81.0);
  for (const char* c : {"D", "E", "S"}) EXPECT_EQ(j[c]["status"], "proven") << c;
  EXPECT_EQ(j["D"]["theorem"], "proofs/cap_d_limit.md");
  EXPECT_EQ(j["A"]["status"], "certified");
  EXPECT_FALSE(j["A"].contains("exact"));
  EXPECT_LT(j["A"]["lower_bound"].get<double>(), j["A"]["value"].get<double>());
  const auto s = run_cli("limits --region sphere --json");
  ASSERT_EQ(s.status, 0) << s.err;
  EXPECT_EQ(Json::parse(s.out)["A"]["theorem"], "proofs/aes_limits.md");
  EXPECT_EQ(Json::parse(s.out)["A"]["status"], "proven");
}

}  // namespace
}  // namespace scalcal::testing
