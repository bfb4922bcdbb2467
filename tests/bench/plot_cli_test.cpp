// scalcal plot as a user runs it: a plan file's figure (both hemispheres, steps joined), a cap's
// (tilt and azimuth), a log's, each with its script and data beside it; a figure never writes over
// its input, and a format other than pdf, png, svg is refused.
#include <filesystem>

#include <gtest/gtest.h>

#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

namespace fs = std::filesystem;

TEST(PlotCli, APlanFileIsDrawnWithItsScriptAndData) {
  const fs::path dir = scratch_dir() / "plot_plan";
  fs::create_directories(dir);
  const std::string design = (dir / "design.csv").string(), plan = (dir / "plan.csv").string();
  ASSERT_EQ(run_cli("plan classic18 --bench gimbal:x,y --resolution 1 --out " + plan).status, 0);
  const CliResult r =
      run_cli("plot " + plan + " --region cap:50 --region cap:50:0,0,-1 --out " + (dir / "plan.svg").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("plot (hemispheres)"), std::string::npos) << r.out;
  for (const char* f : {"plan.gp", "plan.pdf", "plan.png", "plan.svg", "plan_positions.csv", "plan_path.csv",
                        "plan_region0.csv", "plan_region1.csv", "plan_edges.csv"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  const std::string gp = slurp((dir / "plan.gp").string());
  EXPECT_NE(gp.find("Written by `scalcal plot`"), std::string::npos);
  EXPECT_EQ(slurp(plan).rfind("# plan of classic18", 0), 0u);  // the plan file itself is untouched
}

TEST(PlotCli, OneCapIsDrawnAsTiltAndAzimuth) {
  const fs::path dir = scratch_dir() / "plot_cap";
  fs::create_directories(dir);
  const std::string program = (dir / "cap.csv").string();
  ASSERT_EQ(run_cli("optimize --positions 10 --criterion D --region cap:60 --starts 2 --out " + program).status, 0);
  const CliResult r = run_cli("plot " + program + " --out " + (dir / "cap.pdf").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("plot (cap)"), std::string::npos) << r.out;
}

TEST(PlotCli, ALogIsDrawnWithItsCalibration) {
  const fs::path dir = scratch_dir() / "plot_log";
  fs::create_directories(dir);
  const std::string log = (dir / "log.csv").string(), cal = (dir / "cal.json").string();
  ASSERT_EQ(run_cli("simulate --program classic18 --noise 1e-3 --log " + log + " --still 2 --dwell 2 --rate 50").status,
            0);
  ASSERT_EQ(run_cli("calibrate --measurements " + log + " --magnitude 1 --suggest 0 --out " + cal).status, 0);
  const CliResult r =
      run_cli("plot --log " + log + " --calibration " + cal + " --out " + (dir / "figure.png").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "figure_intervals.csv"));
  EXPECT_TRUE(fs::exists(dir / "figure_log.csv"));
  const CliResult alone = run_cli("plot --log " + log);
  EXPECT_EQ(alone.status, 2);
  EXPECT_NE(alone.err.find("--calibration"), std::string::npos) << alone.err;
}

TEST(PlotCli, NeverWritesOverItsInputAndRefusesOtherFormats) {
  const fs::path dir = scratch_dir() / "plot_refuse";
  fs::create_directories(dir);
  const std::string input = write_file("plot_refuse/x_positions.csv",
                                       "x,y,z\n1,0,0\n0,1,0\n0,0,1\n-1,0,0\n0,-1,0\n0,0,-1\n1,1,0\n0,1,1\n1,0,1\n");
  const std::string before = slurp(input);
  const CliResult r = run_cli("plot " + input + " --out " + (dir / "x.pdf").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("over the input"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(input), before);
  const CliResult jpg = run_cli("plot classic18 --out " + (dir / "x.jpg").string());
  EXPECT_EQ(jpg.status, 2);
  EXPECT_NE(jpg.err.find("FILE.pdf, FILE.png or FILE.svg"), std::string::npos) << jpg.err;
}

}  // namespace
}  // namespace scalcal::testing
