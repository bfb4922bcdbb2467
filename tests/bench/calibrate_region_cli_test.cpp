// The program carries its bench: calibrate judges the measured program on the region of the program
// it ran (--program FILE), else on the region line of the log itself (simulate --log copies the
// program's), and --region replaces either with a warning. cap:180 is the sphere written as a cap,
// so its limits cost nothing while the region's text shows which line was used.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using Json = nlohmann::json;

std::string program_with(const std::string& name, const std::string& region) {
  return write_file(name, "# region: " + region +
                              "\nx,y,z\n1,0,0\n-1,0,0\n0,1,0\n0,-1,0\n0,0,1\n0,0,-1\n"
                              "1,1,0\n1,-1,0\n0,1,1\n0,1,-1\n1,0,1\n-1,0,1\n");
}

TEST(CalibrateRegionCli, TheRegionComesFromTheProgramOrTheLog) {
  const std::string program = program_with("carried.csv", "cap:180"),
                    other = program_with("other.csv", "cap:180:1,0,0");
  const std::string log = (scratch_dir() / "carried_log.csv").string();
  ASSERT_EQ(
      run_cli("simulate --program " + program + " --noise 1e-3 --log " + log + " --still 2 --dwell 2 --rate 50").status,
      0);
  EXPECT_EQ(slurp(log).rfind("# region: cap:180\n", 0), 0u);
  const std::string calibrate = "calibrate --measurements " + log + " --magnitude 1 --suggest 1 --json";
  const CliResult from_log = run_cli(calibrate);
  ASSERT_EQ(from_log.status, 0) << from_log.err;
  EXPECT_EQ(Json::parse(from_log.out)["program"]["region"], "cap:180");
  const CliResult from_program = run_cli(calibrate + " --program " + other);
  ASSERT_EQ(from_program.status, 0) << from_program.err;
  EXPECT_EQ(Json::parse(from_program.out)["program"]["region"], "cap:180:1,0,0");
  const CliResult replaced = run_cli(calibrate + " --program " + other + " --region sphere");
  ASSERT_EQ(replaced.status, 0) << replaced.err;
  EXPECT_EQ(Json::parse(replaced.out)["program"]["region"], "sphere");
  EXPECT_NE(replaced.err.find("is replaced by --region"), std::string::npos) << replaced.err;
  const CliResult bad = run_cli(calibrate + " --program " + program_with("bad_region.csv", "cap:400"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("bad_region.csv:1: # region:"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace scalcal::testing
