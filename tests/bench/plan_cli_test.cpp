// `scalcal plan` as a user runs it: the JSON's steps compose to their positions by the stated
// convention (recomputed here), the plan file reads back as the program as run with its region, a
// position out of reach is exit 2 naming it, and a jig's faces are the opposite of its positions.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using Json = nlohmann::json;
constexpr double kDeg = std::numbers::pi / 180;

// A program of 12 positions, 6 within 40 degrees of +z and 6 within 40 of -z, alternating.
std::string two_caps_program() {
  std::string csv = "# region: cap:40;cap:40:0,0,-1\nx,y,z\n";
  for (int i = 0; i < 12; ++i) {
    const double t = (i % 3 == 0 ? 40 : 25 + i) * kDeg, a = (37 * i) * kDeg, z = i % 2 ? -std::cos(t) : std::cos(t);
    csv += std::to_string(std::sin(t) * std::cos(a)) + "," + std::to_string(std::sin(t) * std::sin(a)) + "," +
           std::to_string(z) + "\n";
  }
  return write_file("two_caps.csv", csv);
}

TEST(PlanCli, StepsComposeToTheirPositionsAndTheOrderSavesTravel) {
  const std::string program = two_caps_program();
  const CliResult r = run_cli("plan " + program + " --bench gimbal:x,y --resolution 0.5 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["bench"], "gimbal:x,y");
  EXPECT_EQ(j["region"], "cap:40 + cap:40:0,0,-1");  // from the file's region line
  ASSERT_EQ(j["steps"].size(), 12u);
  for (const auto& s : j["steps"]) {
    const double t1 = s["angles_deg"][0], t2 = s["angles_deg"][1];
    EXPECT_NEAR(std::remainder(t1, 0.5), 0, 1e-9);
    // R = R_x(t1) R_y(t2), eta = R^T e_z = R_y(-t2) (0, sin t1, cos t1).
    const double e[3] = {-std::cos(t1 * kDeg) * std::sin(t2 * kDeg), std::sin(t1 * kDeg),
                         std::cos(t1 * kDeg) * std::cos(t2 * kDeg)};
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(s["eta"][k].get<double>(), e[k], 1e-12);
    const double z = std::abs(e[2]);
    EXPECT_GE(z, std::cos(40 * kDeg) - 1e-12);  // rounding stayed in the caps
    EXPECT_LE(s["rounding_deg"].get<double>(), 1.0);
  }
  EXPECT_LE(j["total_travel_deg"].get<double>(), j["given_order"]["total_travel_deg"].get<double>());
  EXPECT_GT(j["travel_saved_deg"].get<double>(), 0);
  for (const char* c : {"D", "A", "E", "S"}) {
    EXPECT_TRUE(j["criteria"][c].is_number());
    EXPECT_TRUE(j["efficiency_lost"][c].is_number());
  }
}

TEST(PlanCli, ThePlanFileIsTheProgramAsRunWithItsRegion) {
  const std::string program = two_caps_program(), out = (scratch_dir() / "plan_out.csv").string();
  const CliResult r = run_cli("plan " + program + " --bench tilt:40:flip --resolution 0.1 --out " + out + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["remounts"], 1);
  EXPECT_EQ(j["given_order"]["remounts"], 11);
  const std::string file = slurp(out);
  EXPECT_EQ(file.rfind("# region: cap:40;cap:40:0,0,-1\n", 0), 0u) << file;
  EXPECT_NE(file.find("step,position,mounting,tilt_deg,azimuth_deg"), std::string::npos) << file;
  // evaluate reads the region line (judging the program on it takes seconds for A, E, S: the
  // sphere instead, which the region line's warning names).
  const CliResult e = run_cli("evaluate " + out + " --json --region sphere");
  ASSERT_EQ(e.status, 0) << e.err;
  EXPECT_NE(e.err.find("the program's region cap:40;cap:40:0,0,-1 (line 1) is replaced by --region"), std::string::npos)
      << e.err;
  const Json ej = Json::parse(e.out);
  EXPECT_NEAR(ej["D"].get<double>(), j["criteria"]["D"].get<double>(), 1e-9 * j["criteria"]["D"].get<double>());
}

TEST(PlanCli, APositionOutOfReachIsExitTwoNamingIt) {
  const std::string program = two_caps_program();
  const CliResult r = run_cli("plan " + program + " --bench tilt:40");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("6 of 12 positions are beyond the reach of the bench tilt:40: position 2 "), std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  const CliResult bad = run_cli("plan " + program + " --bench gimbal:x,x");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--bench"), std::string::npos) << bad.err;
}

// jig:cuboctahedron's program on its own jig: position i (normal n_i) is run with the face of
// normal -n_i down; tipping is no remount, and the tips sum to the travel.
TEST(PlanCli, AJigRunsEachPositionOnTheOppositeFace) {
  const CliResult r = run_cli("plan jig:cuboctahedron --bench jig:cuboctahedron --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  const CliResult p = run_cli("evaluate jig:cuboctahedron --json");
  const Json program = Json::parse(p.out)["program"];
  EXPECT_EQ(j["remounts"], 0);
  double tips = 0;
  for (std::size_t k = 0; k < j["steps"].size(); ++k) {
    const auto& s = j["steps"][k];
    const auto& down = program[std::stoi(s["face_down"].get<std::string>()) - 1];
    const auto& here = program[s["position"].get<int>() - 1];
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(down[c].get<double>(), -here[c].get<double>(), 1e-12);
    if (k > 0) {
      const auto& before = j["steps"][k - 1]["eta"];
      double dot = 0;
      for (int c = 0; c < 3; ++c) dot += before[c].get<double>() * s["eta"][c].get<double>();
      tips += std::acos(std::clamp(dot, -1.0, 1.0)) / kDeg;
    }
  }
  EXPECT_NEAR(j["total_travel_deg"].get<double>(), tips, 1e-6);
}

}  // namespace
}  // namespace scalcal::testing
