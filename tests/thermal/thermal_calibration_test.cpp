// Thermal logs (issue 53): a rehearsal of a known meter whose parameters drift with temperature,
// calibrated by `scalcal calibrate --model paper9+T2`, against its truth over 20 seeds (the standardised
// errors must look like N(0, 1): RMS within 0.7..1.3, at most 1 % beyond 3), and the refusals.
#include <cmath>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "numeric/program/catalogue.hpp"
#include "tests/common/run_cli.hpp"
#include "tests/thermal/thermal_programs.hpp"

namespace scalcal {
namespace {
using testing::CliResult;
using testing::run_cli;

std::string scratch(const std::string& name) { return (testing::scratch_dir() / ("thermal_" + name)).string(); }

std::string write_program(const std::vector<double>& setpoints, const std::string& name) {
  return testing::write_thermal_program(setpoints, scratch(name));
}

TEST(ThermalCalibration, RehearsalsCalibrateToTheirTruth) {
  const std::string program = write_program({-10, 20, 50}, "program.csv");
  std::vector<double> z;
  for (int seed = 1; seed <= 20; ++seed)
    EXPECT_EQ(
        testing::standardised_errors({"simulate", "--program", program, "--model", "paper9+T2", "--temperature",
                                      "-10..50", "--noise", "1e-3", "--size", "3e-3", "--rate", "50", "--dwell", "4"},
                                     "paper9+T2", "-10..50", seed, scratch("setpoints"), z),
        36u)
        << "seed " << seed;
  int beyond = 0;
  for (double v : z) beyond += std::abs(v) > 3;
  EXPECT_GT(testing::rms(z), 0.7);
  EXPECT_LT(testing::rms(z), 1.3);
  EXPECT_LE(beyond, static_cast<int>(0.01 * static_cast<double>(z.size())) + 1) << z.size() << " errors";
}

// A ramp: the temperature climbs 2 degC per minute from -10 to 50 while the dodecahedron's 12 positions run over
// and over (about 227 poses of 5 s at 20 Hz); 10 seeds, 270 standardised errors.
TEST(ThermalCalibration, RampRehearsalsCalibrateToTheirTruth) {
  std::vector<double> z;
  for (int seed = 1; seed <= 10; ++seed)
    EXPECT_GT(testing::standardised_errors(
                  {"simulate", "--program", "dodecahedral-12", "--model", "paper9+T2", "--temperature", "-10..50",
                   "--ramp", "2", "--noise", "1e-3", "--size", "3e-3", "--rate", "20"},
                  "paper9+T2", "-10..50", seed, scratch("ramp"), z),
              200u)
        << "seed " << seed;
  EXPECT_GT(testing::rms(z), 0.7);
  EXPECT_LT(testing::rms(z), 1.3);
  // The ramp sets the temperatures: a program with its own is refused, and so is a ramp without a thermal model.
  const std::string program = write_program({0, 40}, "ramp_program.csv");
  EXPECT_EQ(run_cli({"simulate", "--program", program, "--model", "paper9+T1", "--temperature", "0..40", "--ramp", "1",
                     "--log", scratch("x.csv"), "--noise", "1e-3"})
                .status,
            2);
  EXPECT_EQ(
      run_cli({"simulate", "--program", "dodecahedral-12", "--ramp", "1", "--log", scratch("x.csv"), "--noise", "1e-3"})
          .status,
      2);
  // A ramp too slow for the rehearsal's 2e7 samples is the options' fault: exit 2 naming them, not an internal error.
  const CliResult slow = run_cli({"simulate", "--program", "dodecahedral-12", "--model", "paper9+T2", "--temperature",
                                  "-20..60", "--ramp", "0.0001", "--log", scratch("x.csv"), "--noise", "1e-3"});
  EXPECT_EQ(slow.status, 2);
  EXPECT_NE(slow.err.find("--ramp"), std::string::npos) << slow.err;
}

// plot --log draws a thermal calibration's poses: the raw log with the poses shaded, and each pose's residual
// against its temperature; another log's calibration is refused.
TEST(ThermalCalibration, PlotLogDrawsTheResidualAgainstTemperature) {
  const std::string program = write_program({0, 20, 40}, "plot_program.csv"), log = scratch("plot_log.csv"),
                    other = scratch("plot_other.csv"), cal = scratch("plot_cal.json"), figure = scratch("plot_fig.svg");
  for (const auto& [file, seed] : {std::pair{log, "4"}, std::pair{other, "5"}})
    ASSERT_EQ(run_cli({"simulate", "--program", program, "--model", "paper9+T2", "--temperature", "0..40", "--log",
                       file, "--noise", "1e-3", "--seed", seed, "--rate", "50"})
                  .status,
              0);
  ASSERT_EQ(
      run_cli({"calibrate", "--measurements", log, "--model", "paper9+T2", "--magnitude", "1", "--out", cal}).status,
      0);
  const CliResult p = run_cli({"plot", "--log", log, "--calibration", cal, "--out", figure});
  ASSERT_EQ(p.status, 0) << p.err;
  std::ifstream in(scratch("plot_fig_intervals.csv"));
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header, "interval,start,end,before,after,t_c");
  std::vector<double> celsius;
  while (std::getline(in, line)) celsius.push_back(std::stod(line.substr(line.rfind(',') + 1)));
  ASSERT_EQ(celsius.size(), 36u);
  EXPECT_NEAR(celsius.front(), 0, 0.5);
  EXPECT_NEAR(celsius.back(), 40, 0.5);
  EXPECT_NE(testing::slurp(scratch("plot_fig.gp")).find("temperature"), std::string::npos);
  const CliResult wrong = run_cli({"plot", "--log", other, "--calibration", cal, "--out", scratch("wrong.svg")});
  EXPECT_EQ(wrong.status, 2);
  EXPECT_NE(wrong.err.find("another log's calibration"), std::string::npos) << wrong.err;
}

// The other bases whose meter corrects as a matrix and an offset: axis6 (bias and scale factor drift) and bias3 (the
// offsets drift, as PX4 and ArduPilot fit them), 20 seeds each; their coefficients' standardised errors pooled (here
// RMS 0.985, 1.101, 1.029 over 360, 240, 240 errors, 3, 2, 0 beyond 3).
TEST(ThermalCalibration, LinearBasesCalibrateToTheirTruth) {
  const std::string three = write_program({-10, 20, 50}, "linear3.csv"),
                    four = write_program({-10, 10, 30, 50}, "l4.csv");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"axis6+T2", three}, {"axis6+bias:T2", three}, {"bias3+T3", four}};
  for (const auto& [model, program] : cases) {
    std::vector<double> z;
    for (int seed = 1; seed <= 20; ++seed)
      EXPECT_EQ(
          testing::standardised_errors({"simulate", "--program", program, "--model", model, "--temperature", "-10..50",
                                        "--noise", "1e-3", "--size", "3e-3", "--rate", "50", "--dwell", "4"},
                                       model, "-10..50", seed, scratch("linear"), z),
          program == three ? 36u : 48u)
          << model << " seed " << seed;
    int beyond = 0;
    for (double v : z) beyond += std::abs(v) > 3;
    EXPECT_GT(testing::rms(z), 0.7) << model;
    EXPECT_LT(testing::rms(z), 1.3) << model;
    EXPECT_LE(beyond, static_cast<int>(0.01 * static_cast<double>(z.size())) + 1) << model << ": " << z.size();
  }
}

// cubic12's correction is not a matrix and an offset: neither rehearsed nor fitted as a thermal base, and the refusal
// names the bases that would do.
TEST(ThermalCalibration, ANonlinearBaseIsRefusedNamingTheBases) {
  const std::string program = write_program({0, 40}, "cubic.csv"), log = scratch("cubic_log.csv");
  const CliResult s = run_cli({"simulate", "--program", program, "--model", "cubic12+T1", "--temperature", "0..40",
                               "--log", log, "--noise", "1e-3"});
  EXPECT_EQ(s.status, 2);
  EXPECT_NE(s.err.find("with BASE one of paper9, axis6, bias3 (got --model cubic12+T1)"), std::string::npos) << s.err;
  ASSERT_EQ(run_cli({"simulate", "--program", program, "--model", "paper9+T1", "--temperature", "0..40", "--log", log,
                     "--noise", "1e-3", "--rate", "50"})
                .status,
            0);
  const CliResult c = run_cli({"calibrate", "--measurements", log, "--model", "cubic12+T1", "--magnitude", "1"});
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.err.find("with BASE one of paper9, axis6, bias3"), std::string::npos) << c.err;
}

TEST(ThermalCalibration, TooFewSetPointsAreRefusedWithWhatWouldWork) {
  const std::string program = write_program({0, 40}, "two.csv"), log = scratch("two_log.csv");
  ASSERT_EQ(run_cli({"simulate", "--program", program, "--model", "paper9+T2", "--temperature", "0..40", "--log", log,
                     "--noise", "1e-3", "--seed", "3", "--rate", "50"})
                .status,
            0);
  const CliResult c = run_cli({"calibrate", "--measurements", log, "--model", "paper9+T2", "--magnitude", "1"});
  EXPECT_EQ(c.status, 2);
  EXPECT_NE(c.err.find("needs 3 set-points at least"), std::string::npos) << c.err;
  // The same log identifies degree 1.
  EXPECT_EQ(run_cli({"calibrate", "--measurements", log, "--model", "paper9+T1", "--magnitude", "1"}).status, 0);
  // No temperature column: the plain log of a rehearsal.
  const CliResult plain = run_cli({"calibrate", "--measurements", SCALCAL_SOURCE_DIR "/data/table1_A.csv", "--model",
                                   "paper9+T1", "--magnitude", "1"});
  EXPECT_EQ(plain.status, 2) << plain.err;
  EXPECT_EQ(run_cli({"calibrate", "--measurements", log, "--model", "paper9+T1", "--magnitude", "auto"}).status, 2);
}

}  // namespace
}  // namespace scalcal
