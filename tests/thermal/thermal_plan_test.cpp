// Thermal plans (issue 53): `scalcal plan` on a program with a temperature column runs the set-points from the
// coldest, each set-point's positions in the bench's order (the next set-point starting where the last one
// ended), with a soak per set-point and a rest per position in its time; the plan file reads back as the
// same thermal program.
#include <cmath>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "numeric/program/catalogue.hpp"
#include "tests/common/run_cli.hpp"

namespace scalcal {
namespace {
using testing::CliResult;
using testing::run_cli;

std::string scratch(const std::string& name) { return (testing::scratch_dir() / ("thermal_plan_" + name)).string(); }

// The dodecahedron's 12 normals at 60, -20 and 20 degC, the set-points interleaved row by row (not oven order).
std::string interleaved_program() {
  const std::string path = scratch("program.csv");
  std::ofstream out(path);
  out.precision(17);
  out << "x,y,z,t_c\n";
  const Program p = *named_program("dodecahedral-12");
  for (const auto& e : p.positions)
    for (double t : {60.0, -20.0, 20.0}) out << e(0) << "," << e(1) << "," << e(2) << "," << t << "\n";
  return path;
}

TEST(ThermalPlan, SetPointsFromTheColdestEachWithAllItsPositions) {
  const std::string program = interleaved_program(), planned = scratch("planned.csv");
  const CliResult c =
      run_cli({"plan", program, "--bench", "gimbal:x,y", "--soak", "40", "--dwell", "8", "--json", "--out", planned});
  ASSERT_EQ(c.status, 0) << c.err;
  const auto j = nlohmann::json::parse(c.out);
  ASSERT_EQ(j["setpoints"].size(), 3u);
  const double expected[3] = {-20, 20, 60};
  const auto& steps = j["steps"];
  ASSERT_EQ(steps.size(), 36u);
  for (int s = 0; s < 3; ++s) {
    const auto& sp = j["setpoints"][static_cast<std::size_t>(s)];
    EXPECT_EQ(sp["t_c"].get<double>(), expected[s]);
    EXPECT_EQ(sp["first_step"].get<int>(), 1 + 12 * s);
    EXPECT_EQ(sp["steps"].get<int>(), 12);
    // Rows 1-based: row r of the file is position (r - 1) / 3 at set-point (60, -20, 20)[(r - 1) % 3].
    std::set<int> positions;
    for (int k = 12 * s; k < 12 * s + 12; ++k) {
      const int row = steps[static_cast<std::size_t>(k)]["position"].get<int>() - 1;
      EXPECT_EQ((row % 3 + 2) % 3, s) << "step " << k + 1;  // 60 -> 2, -20 -> 0, 20 -> 1
      positions.insert(row / 3);
    }
    EXPECT_EQ(positions.size(), 12u);
  }
  // The next set-point starts where the last one ended: no travel between set-points.
  for (int k : {11, 23})
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(steps[static_cast<std::size_t>(k)]["eta"][static_cast<std::size_t>(a)].get<double>(),
                  steps[static_cast<std::size_t>(k + 1)]["eta"][static_cast<std::size_t>(a)].get<double>(), 1e-12);
  // Time: 3 soaks of 40 min, 36 rests of 8 s, the travel at 45 deg/s.
  EXPECT_NEAR(j["total_s"].get<double>(), 3 * 2400 + 36 * 8 + j["total_travel_deg"].get<double>() / 45, 1e-9);
  // The plan file is the same thermal program: evaluate gives the same D.
  const CliResult a = run_cli({"evaluate", program, "--model", "paper9+T2", "--temperature", "-20..60", "--json"});
  const CliResult b = run_cli({"evaluate", planned, "--model", "paper9+T2", "--temperature", "-20..60", "--json"});
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  const auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  EXPECT_NEAR(jb["criteria"]["D"].get<double>() / ja["criteria"]["D"].get<double>(), 1, 1e-9) << a.out.substr(0, 400);
}

TEST(ThermalPlan, SoakBelongsToAThermalProgram) {
  const CliResult c = run_cli({"plan", "dodecahedral-12", "--bench", "gimbal:x,y", "--soak", "10"});
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.err.find("--soak belongs to a thermal program"), std::string::npos) << c.err;
}

}  // namespace
}  // namespace scalcal
