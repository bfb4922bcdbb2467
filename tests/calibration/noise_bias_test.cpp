// A tumbling magnetometer whose noise is a few percent of the field (the public QMC5883L's: 58, 56, 62
// counts per axis on gains of about 1075, 740, 1603) biases a fit of single samples by the noise's
// square, anisotropically: the y gain by 5 to 8 standard errors (embedded/tests/anisotropic_noise.py,
// and an independent SciPy least-squares fit alike). `calibrate` takes that bias off (noise_bias.hpp).
// Simulated here independently of scalcal's simulator (the script's meter and motion, written out):
// the truth is the simulation's, and every parameter must come back within its printed error.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using Json = nlohmann::json;
using V = std::array<double, 3>;

constexpr V kGain = {1075.0, 740.5, 1603.0}, kOffset = {6154.0, 254.0, 3447.0}, kGamma = {0.06, 0.10, 0.01};
constexpr V kNoise = {58.0, 56.0, 62.0};

V normalised(V v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}
double dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Box-Muller from mt19937_64's 53-bit uniforms: the same numbers on every platform.
struct Gauss {
  std::mt19937_64 engine;
  double uniform() { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }
  double operator()() {
    const double u1 = 1 - uniform(), u2 = uniform();
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
  }
};

// Great circles through random directions at 60 degrees per second, 50 Hz, 22743 samples (the real
// log's length); sensor k's axis is row k of Phi, whose off-diagonals split gamma evenly.
void simulate(const std::string& path, std::uint64_t seed) {
  Gauss g{std::mt19937_64(seed)};
  const V p = {kGamma[0] / 2, kGamma[1] / 2, kGamma[2] / 2};
  const double phi[3][3] = {{std::sqrt(1 - p[0] * p[0] - p[2] * p[2]), p[0], p[2]},
                            {p[0], std::sqrt(1 - p[0] * p[0] - p[1] * p[1]), p[1]},
                            {p[2], p[1], std::sqrt(1 - p[2] * p[2] - p[1] * p[1])}};
  const auto random_direction = [&] { return normalised({g(), g(), g()}); };
  const double step = 60.0 / 50 * M_PI / 180;
  V d = random_direction(), to = d;
  int left = 0;
  std::ofstream out(path);
  out << "ix,iy,iz\n";
  char line[96];
  for (int t = 0; t < 22743; ++t) {
    if (left <= 0) {
      to = random_direction();
      left = 1 + static_cast<int>(std::acos(std::clamp(dot(d, to), -1.0, 1.0)) / step);
    }
    const double c = dot(d, to);
    const V a = {to[0] - c * d[0], to[1] - c * d[1], to[2] - c * d[2]};
    if (dot(a, a) > 1e-20) {
      const V u = normalised(a);
      d = normalised({d[0] * std::cos(step) + u[0] * std::sin(step), d[1] * std::cos(step) + u[1] * std::sin(step),
                      d[2] * std::cos(step) + u[2] * std::sin(step)});
    }
    --left;
    V m;
    for (int i = 0; i < 3; ++i)
      m[i] = kOffset[i] + kGain[i] * (phi[i][0] * d[0] + phi[i][1] * d[1] + phi[i][2] * d[2]) + kNoise[i] * g();
    std::snprintf(line, sizeof line, "%.3f,%.3f,%.3f\n", m[0], m[1], m[2]);
    out << line;
  }
}

TEST(NoiseBias, ATumblingLogsGainsComeBackWithinTheirErrors) {
  const std::string log = (scratch_dir() / "qmc_like.csv").string();
  std::vector<double> z;
  double largest_gain_shift = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    simulate(log, seed);
    const CliResult c = run_cli("calibrate --measurements " + log + " --rate 50 --magnitude auto --suggest 0 --json");
    ASSERT_EQ(c.status, 0) << c.err;
    const Json cal = Json::parse(c.out);
    ASSERT_EQ(cal["positions_from"], "every sample") << seed;
    ASSERT_TRUE(cal["converged"]) << seed;
    ASSERT_EQ(cal["tumbling"]["noise_bias"]["replicates"], 16) << seed;
    for (int k = 0; k < 3; ++k) {
      z.push_back((cal["bias"][k].get<double>() - kOffset[k]) / cal["bias_std"][k].get<double>());
      z.push_back((cal["gain"][k].get<double>() - kGain[k]) / cal["gain_std"][k].get<double>());
      z.push_back((cal["nonorthogonality"][k].get<double>() - kGamma[k]) /
                  cal["nonorthogonality_std"][k].get<double>());
      // What was taken off, in the gain's own errors: without it the fit would miss by this much.
      largest_gain_shift =
          std::max(largest_gain_shift,
                   std::abs(cal["tumbling"]["noise_bias"]["gain"][k].get<double>() / cal["gain_std"][k].get<double>()));
    }
  }
  double ss = 0, worst = 0;
  for (double x : z) ss += x * x, worst = std::max(worst, std::abs(x));
  const double rms = std::sqrt(ss / static_cast<double>(z.size()));
  RecordProperty("rms_z", std::to_string(rms));
  EXPECT_LT(rms, 1.6) << "27 standardised errors";
  EXPECT_LT(worst, 3.5);
  // The bias is material here (the test would fail without its removal): at least 4 standard errors.
  EXPECT_GT(largest_gain_shift, 4.0);
}

}  // namespace
}  // namespace scalcal::testing
