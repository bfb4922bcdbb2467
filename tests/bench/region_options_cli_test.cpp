// The boundaries (issue 32 item 2): optimize --margin designs inside the region by the margin and
// judges the program against the region itself; evaluate --tolerance is how far outside a position
// may lie (default 0.05 degrees: a rim position set on a 0.1-degree bench) before it is refused.
#include <cmath>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "commands/core/region_request.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/program_csv.hpp"
#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using Json = nlohmann::json;
constexpr double kDeg = std::numbers::pi / 180;

TEST(RegionOptionsCli, MarginDesignsInsideAndJudgesOnTheRegion) {
  const std::string out = (scratch_dir() / "margin.csv").string();
  const CliResult r =
      run_cli("optimize --positions 12 --criterion D --region cap:40 --margin 0.5 --starts 2 --json --out " + out);
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = Json::parse(r.out);
  EXPECT_EQ(j["region"], "cap:40");
  EXPECT_EQ(j["designed_on"], "cap:40 inset by 0.5 deg");
  double widest = 0;
  for (const auto& x : j["program"])
    widest = std::max(widest, std::acos(std::clamp(x[2].get<double>(), -1.0, 1.0)) / kDeg);
  EXPECT_LE(widest, 39.5 + 1e-6);
  EXPECT_GT(widest, 39.4);  // the optimum still uses the (inset) rim
  EXPECT_LT(j["efficiency"].get<double>(), 1.0);
  EXPECT_EQ(slurp(out).rfind("# region: cap:40\n", 0), 0u);  // the file carries the bench's region, not the inset
  const CliResult none = run_cli("optimize --positions 12 --criterion D --margin 0.5");
  EXPECT_EQ(none.status, 2);
  const CliResult too_wide = run_cli("optimize --positions 12 --criterion D --region cap:5 --margin 6");
  EXPECT_EQ(too_wide.status, 2);
  EXPECT_NE(too_wide.err.find("--margin"), std::string::npos) << too_wide.err;
}

TEST(RegionOptionsCli, EvaluateToleranceDecidesWhatIsOutside) {
  // Nine positions inside cap:40 and one at 40.03 degrees.
  std::ostringstream csv;
  csv << "x,y,z\n";
  const double tilts[10] = {0, 20, 20, 20, 35, 35, 35, 35, 10, 40.03};
  for (int i = 0; i < 10; ++i) {
    const double t = tilts[i] * kDeg, a = (40.0 * i + 7) * kDeg;
    csv.precision(17);
    csv << std::sin(t) * std::cos(a) << "," << std::sin(t) * std::sin(a) << "," << std::cos(t) << "\n";
  }
  const std::string program = write_file("tolerance.csv", csv.str());
  // Kept by the default tolerance (the check itself: judging the program on cap:40 takes seconds).
  const Program p = read_program_csv(program);
  EXPECT_NO_THROW(commands::refuse_outside(program, p, parse_region({"cap:40"}), commands::kDefaultToleranceDeg));
  EXPECT_THROW(commands::refuse_outside(program, p, parse_region({"cap:40"}), 0.02), InputError);
  const CliResult refused = run_cli("evaluate " + program + " --region cap:40 --tolerance 0.01");
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("position 10 (tilt 40.03 deg)"), std::string::npos) << refused.err;
}

}  // namespace
}  // namespace scalcal::testing
