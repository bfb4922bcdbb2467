// Thermal models on a region (issue 53): Theorem 25's product on region x [T1, T2], the region's factor from
// `limits --region` (a cap's theorem or certified bounds) times the interval's exact factor, labelled by what
// stands behind both; a product program designed on the region judged against that limit.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/run_cli.hpp"

namespace scalcal {
namespace {
using testing::CliResult;
using testing::run_cli;

nlohmann::json json_of(const std::vector<std::string>& args) {
  const CliResult c = run_cli(args);
  EXPECT_EQ(c.status, 0) << c.err;
  return nlohmann::json::parse(c.out);
}

TEST(ThermalRegion, CapLimitsAreTheCapsTimesTheIntervals) {
  const auto base = json_of({"limits", "--region", "cap:60", "--json"});
  const auto t =
      json_of({"limits", "--model", "paper9+T2", "--temperature", "-20..60", "--region", "cap:60", "--json"});
  // D: D_cap^3 (27/4)^9, proven (Theorem 8 on the cap, the Lobatto points on the interval).
  EXPECT_EQ(t["D"]["status"], "proven");
  EXPECT_NEAR(t["D"]["value"].get<double>() / (std::pow(base["D"]["value"].get<double>(), 3) * std::pow(27.0 / 4, 9)),
              1, 1e-12);
  // E and S: the cap's closed forms 5283 and 2401 (Theorem 19) times 5 and 4.
  EXPECT_EQ(t["E"]["status"], "proven");
  EXPECT_NEAR(t["E"]["value"].get<double>(), 5283.0 * 5, 1e-6);
  EXPECT_EQ(t["S"]["status"], "proven");
  EXPECT_NEAR(t["S"]["value"].get<double>(), 2401.0 * 4, 1e-6);
  // A: the cap's certified enclosure times 8, still certified.
  EXPECT_EQ(t["A"]["status"], "certified");
  EXPECT_NEAR(t["A"]["value"].get<double>() / (8 * base["A"]["value"].get<double>()), 1, 1e-12);
  EXPECT_NEAR(t["A"]["lower_bound"].get<double>() / (8 * base["A"]["lower_bound"].get<double>()), 1, 1e-12);
}

TEST(ThermalRegion, BiasOnlyModelsHaveNoRegionLimit) {
  const auto t =
      json_of({"limits", "--model", "paper9+bias:T2", "--temperature", "0..40", "--region", "cap:60", "--json"});
  for (const char* c : {"D", "A", "E", "S"}) EXPECT_TRUE(t[c]["value"].is_null()) << c;
}

TEST(ThermalRegion, AProductProgramOnTheCapIsJudgedOnTheCap) {
  const std::string program = (testing::scratch_dir() / "thermal_region_cap.csv").string();
  const CliResult o = run_cli({"optimize", "--model", "paper9+T2", "--temperature", "-20..60", "--criterion", "D",
                               "--positions", "36", "--region", "cap:60", "--seed", "1", "--out", program});
  ASSERT_EQ(o.status, 0) << o.err;
  const auto on_cap = json_of(
      {"evaluate", program, "--model", "paper9+T2", "--temperature", "-20..60", "--region", "cap:60", "--json"});
  const auto on_sphere = json_of({"evaluate", program, "--model", "paper9+T2", "--temperature", "-20..60", "--json"});
  const double eff = on_cap["efficiency"]["D"].get<double>();
  EXPECT_GT(eff, 0.95);
  EXPECT_LE(eff, 1 + 1e-9);
  // Against the sphere's limit the same program is far from efficient (the cap's D limit is 1.4e6 x the sphere's).
  EXPECT_LT(on_sphere["efficiency"]["D"].get<double>(), 0.7);
  // A position outside the region is refused.
  const CliResult outside =
      run_cli({"evaluate", program, "--model", "paper9+T2", "--temperature", "-20..60", "--region", "cap:30"});
  EXPECT_EQ(outside.status, 2) << outside.err;
}

}  // namespace
}  // namespace scalcal
