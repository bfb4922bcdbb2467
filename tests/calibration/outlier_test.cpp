// Outlier samples: one sample 10x off in otherwise good bench data (independent simulator). With
// it the estimator leaves the linearised model; excluded, the estimate is back within four
// standard errors of the true meter. Clean and quantised data lose nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "numeric/calibration/outlier_samples.hpp"
#include "numeric/calibration/scalar_calibration.hpp"
#include "tests/calibration/independent_simulator.hpp"

namespace {

using namespace calibration_test;
using scalcal::PositionSamples;
using scalcal::Vec3;

constexpr double kG = 9.80665;

// classic18 with `samples` samples per position, lines numbered as a file with a header would.
std::vector<PositionSamples> bench(const TrueMeter& m, double sigma, int samples, std::uint64_t seed) {
  Noise rng(seed);
  std::vector<PositionSamples> out;
  int line = 2;
  for (const V3& eta : classic18_positions()) {
    const V3 clean = m.measure({eta[0] * kG, eta[1] * kG, eta[2] * kG});
    PositionSamples p;
    p.line = line;
    for (int s = 0; s < samples; ++s) {
      p.samples.push_back(
          Vec3(clean[0] + sigma * rng.gauss(), clean[1] + sigma * rng.gauss(), clean[2] + sigma * rng.gauss()));
      p.sample_lines.push_back(line++);
    }
    out.push_back(p);
  }
  return out;
}

scalcal::CalibrationResult calibrate(const std::vector<PositionSamples>& data) {
  scalcal::CalibrationOptions o;
  o.magnitude = kG;
  return scalcal::calibrate(data, o);
}

// The largest error of the estimate in units of `std` (standard errors of a clean fit).
double worst_error_in(const scalcal::CalibrationResult& r, const scalcal::Vec9& std, const TrueMeter& m) {
  const double truth[9] = {m.bias[0] / kG, m.bias[1] / kG, m.bias[2] / kG, m.dk[0],     m.dk[1],
                           m.dk[2],        m.gamma()[0],   m.gamma()[1],   m.gamma()[2]};
  double worst = 0;
  for (int k = 0; k < 9; ++k) worst = std::max(worst, std::abs(r.X(k) - truth[k]) / std(k));
  return worst;
}

TEST(OutlierSamples, OneSampleTenTimesOffIsExcludedByLine) {
  const double sigma = 5e-3;
  const TrueMeter m = example_meter(2e-3, kG);
  auto data = bench(m, sigma, 10, 11);
  data[7].samples[4] *= 10.0;  // the line of that sample: 2 + 7 * 10 + 4
  const auto kept = calibrate(data);
  const auto out = scalcal::exclude_outlier_samples(data);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].line, 2 + 7 * 10 + 4);
  EXPECT_EQ(out[0].position, 7);
  EXPECT_GT(out[0].distance, 1000);  // 9 g against noise of 5e-3: thousands of scales
  EXPECT_EQ(data[7].samples.size(), 9u);
  EXPECT_EQ(data[7].sample_lines.size(), 9u);
  const auto r = calibrate(data);
  ASSERT_TRUE(r.summary.converged());
  EXPECT_EQ(r.samples, 179);
  EXPECT_NEAR(r.noise / sigma, 1.0, 0.2);
  EXPECT_LT(worst_error_in(r, r.X_std, m), 4.0);
  // The test can fail: kept, the sample inflates the noise estimate and moves the estimate by many
  // standard errors of the clean fit.
  EXPECT_GT(kept.noise / sigma, 10.0);
  EXPECT_GT(worst_error_in(kept, r.X_std, m), 20.0);
}

TEST(OutlierSamples, GaussianNoiseAloneLosesNothing) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    auto data = bench(example_meter(2e-3, kG), 5e-3, 25, seed);
    EXPECT_TRUE(scalcal::exclude_outlier_samples(data).empty()) << "seed " << seed;
  }
}

// Most samples equal to the median (a quantised log): the scale falls back to the typical
// non-zero distance, so one-quantum samples stay and a gross error still goes.
TEST(OutlierSamples, QuantisedDataKeepsOneQuantumSamples) {
  const double q = 1e-3;
  auto data = bench(example_meter(2e-3, kG), 0, 20, 3);
  for (auto& p : data)
    for (auto& s : p.samples) s = (s / q).array().round().matrix() * q;
  for (std::size_t p = 0; p < data.size(); ++p) data[p].samples[p % 20](p % 3) += q;  // one quantum off
  auto clean = data;
  EXPECT_TRUE(scalcal::exclude_outlier_samples(clean).empty());
  data[3].samples[0](0) += 5.0;
  const auto out = scalcal::exclude_outlier_samples(data);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].position, 3);
}

// A position whose samples scatter widely is not "a few bad samples": it is left whole.
TEST(OutlierSamples, ANoisyPositionIsKeptWhole) {
  auto data = bench(example_meter(2e-3, kG), 5e-3, 12, 5);
  Noise rng(99);
  for (auto& s : data[2].samples) s += Vec3(rng.gauss(), rng.gauss(), rng.gauss());  // 200x the noise
  EXPECT_TRUE(scalcal::exclude_outlier_samples(data).empty());
  EXPECT_EQ(data[2].samples.size(), 12u);
}

}  // namespace
