// simulate --log rehearses a program: calibrating the log must give back the true parameters it
// was made with, within the uncertainty calibrate reports. Over 20 seeds (180 standardised errors
// z = (estimate - truth) / std) the z's must look standard normal: their RMS within 0.8..1.2 (its
// sampling spread is 1/sqrt(360) = 0.05), none beyond 4.5 and at most 3 beyond 3 (0.5 expected). The
// true offset and matrix are checked by correcting each resting position's mean: |corrected| = |I|.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using Json = nlohmann::json;

constexpr double kMagnitude = 9.80665;

TEST(RehearsalCli, ALogCalibratesToItsTruthWithinTheReportedUncertainty) {
  const std::string program = write_file("rehearsed.csv",
                                         "x,y,z\n1,0,0\n-1,0,0\n0,1,0\n0,-1,0\n0,0,1\n0,0,-1\n"
                                         "1,1,0\n1,-1,0\n0,1,1\n0,1,-1\n1,0,1\n-1,0,1\n"
                                         "1,1,1\n-1,1,1\n1,-1,1\n1,1,-1\n");
  const std::string log = (scratch_dir() / "rehearsal.csv").string(), truth = (scratch_dir() / "truth.json").string();
  std::vector<double> z;
  for (int seed = 1; seed <= 20; ++seed) {
    const CliResult s =
        run_cli("simulate --program " + program + " --noise 1e-3 --log " + log + " --truth " + truth + " --seed " +
                std::to_string(seed) + " --still 3 --dwell 3 --rate 50 --magnitude 9.80665");
    ASSERT_EQ(s.status, 0) << s.err;
    const CliResult c = run_cli("calibrate --measurements " + log + " --magnitude 9.80665 --still 3 --json");
    ASSERT_EQ(c.status, 0) << c.err;
    const Json cal = Json::parse(c.out), t = Json::parse(slurp(truth));
    ASSERT_EQ(cal["positions"], 16) << "seed " << seed;
    for (const char* key : {"bias", "scale_deviation", "nonorthogonality"})
      for (int k = 0; k < 3; ++k)
        z.push_back((cal[key][k].get<double>() - t[key][k].get<double>()) /
                    cal[std::string(key) + "_std"][k].get<double>());
  }
  double ss = 0, worst = 0;
  int beyond3 = 0;
  for (double x : z) {
    ss += x * x;
    worst = std::max(worst, std::abs(x));
    beyond3 += std::abs(x) > 3;
  }
  const double rms = std::sqrt(ss / static_cast<double>(z.size()));
  EXPECT_GT(rms, 0.8);
  EXPECT_LT(rms, 1.2);
  EXPECT_LT(worst, 4.5);
  EXPECT_LE(beyond3, 3);
}

// The truth's offset and matrix follow calibrate's convention physical = matrix (raw - offset): each
// position's resting samples, averaged and corrected, have the modulus |I| (to 5 noise standard errors).
TEST(RehearsalCli, TheTrueCorrectionMakesEveryRestingPositionModulusI) {
  const std::string bench = (scratch_dir() / "grouped.csv").string(), truth = (scratch_dir() / "truth_g.json").string();
  const CliResult s = run_cli("simulate --program classic18 --noise 1e-3 --bench-file " + bench + " --truth " + truth +
                              " --dwell 2 --rate 50 --size 0.01 --magnitude 9.80665");
  ASSERT_EQ(s.status, 0) << s.err;
  const Json t = Json::parse(slurp(truth));
  std::istringstream in(slurp(bench));
  std::string line;
  std::map<int, std::vector<std::array<double, 3>>> samples;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'p') continue;
    std::array<double, 7> v{};
    std::istringstream fields(line);
    for (double& x : v) {
      std::string f;
      std::getline(fields, f, ',');
      x = std::stod(f);
    }
    samples[static_cast<int>(v[0])].push_back({v[4], v[5], v[6]});
  }
  ASSERT_EQ(samples.size(), 18u);
  for (const auto& [position, rows] : samples) {
    double mean[3] = {0, 0, 0};
    for (const auto& r : rows)
      for (int k = 0; k < 3; ++k) mean[k] += r[static_cast<std::size_t>(k)] / static_cast<double>(rows.size());
    double corrected[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        corrected[i] += t["matrix"][i][k].get<double>() * (mean[k] - t["offset"][k].get<double>());
    const double modulus =
        std::sqrt(corrected[0] * corrected[0] + corrected[1] * corrected[1] + corrected[2] * corrected[2]);
    EXPECT_NEAR(modulus, kMagnitude, 5 * 1e-3 * kMagnitude / std::sqrt(static_cast<double>(rows.size()))) << position;
  }
}

}  // namespace
}  // namespace scalcal::testing
