// A planar layout whose gain is fitted too (issue 54's finding, in the CLI): 20 positions on one tilted circle,
// logged in counts (1000 per |I|), calibrated with the field's modulus in other units (--magnitude 1: the gain
// estimated from the data). bias3 trades the offset along the circle's normal against the gain there, so it is
// refused; with the modulus in the log's own units (the gain known) the same positions calibrate.
#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/common/run_cli.hpp"

namespace scalcal {
namespace {
using testing::CliResult;
using testing::run_cli;

std::string circle_log() {
  const std::string program = (testing::scratch_dir() / "planar_circle.csv").string(),
                    log = (testing::scratch_dir() / "planar_log.csv").string();
  // The circle n . eta = 1/2 about n = (0.3, 0.4, sqrt(0.75)) normalised.
  const double n0[3] = {0.3, 0.4, std::sqrt(0.75)};
  const double nn = std::sqrt(n0[0] * n0[0] + n0[1] * n0[1] + n0[2] * n0[2]);
  const double n[3] = {n0[0] / nn, n0[1] / nn, n0[2] / nn};
  double u[3] = {0, n[2], -n[1]};  // n x (1, 0, 0)
  const double un = std::sqrt(u[1] * u[1] + u[2] * u[2]);
  u[1] /= un, u[2] /= un;
  const double v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
  std::ofstream out(program);
  out.precision(17);
  out << "x,y,z\n";
  for (int k = 0; k < 20; ++k) {
    const double a = 2 * M_PI * k / 20, c = std::sqrt(0.75) * std::cos(a), s = std::sqrt(0.75) * std::sin(a);
    out << 0.5 * n[0] + c * u[0] + s * v[0] << "," << 0.5 * n[1] + c * u[1] + s * v[1] << ","
        << 0.5 * n[2] + c * u[2] + s * v[2] << "\n";
  }
  out.close();
  EXPECT_EQ(run_cli({"simulate", "--program", program, "--log", log, "--noise", "1e-3", "--magnitude", "1000", "--seed",
                     "2", "--rate", "50"})
                .status,
            0);
  return log;
}

TEST(PlanarLayout, GainFittedTooIsRefusedGainKnownCalibrates) {
  const std::string log = circle_log();
  for (const char* model : {"bias3", "auto"}) {
    const CliResult r = run_cli({"calibrate", "--measurements", log, "--magnitude", "1", "--model", model});
    EXPECT_EQ(r.status, 2) << model << ": " << r.out.substr(0, 300);
    EXPECT_NE(r.err.find("trades against the gain"), std::string::npos) << r.err;
  }
  const CliResult known = run_cli({"calibrate", "--measurements", log, "--magnitude", "1000", "--model", "bias3"});
  EXPECT_EQ(known.status, 0) << known.err;
}

}  // namespace
}  // namespace scalcal
