// The iterative estimator on data from the independent simulator: exact recovery without noise,
// recovery within a few standard errors with noise, the effect of bench errors on each modulus.
#include <gtest/gtest.h>

#include <cmath>

#include "numeric/calibration/scalar_calibration.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "tests/calibration/independent_simulator.hpp"

namespace {

using namespace calibration_test;
using scalcal::CalibrationOptions;
using scalcal::CalibrationResult;
using scalcal::Modulus;
using scalcal::PositionSamples;
using scalcal::Vec3;

constexpr double kG = 9.80665;

std::vector<PositionSamples> bench(const TrueMeter& m, double magnitude, double sigma, int samples, double tilt_rad,
                                   std::uint64_t seed) {
  Noise rng(seed);
  std::vector<PositionSamples> out;
  for (const V3& eta : classic18_positions()) {
    const V3 real = tilt_rad > 0 ? tipped(eta, tilt_rad, rng) : eta;
    const V3 clean = m.measure({real[0] * magnitude, real[1] * magnitude, real[2] * magnitude});
    PositionSamples p;
    p.nominal = Vec3(eta[0], eta[1], eta[2]);
    for (int s = 0; s < samples; ++s)
      p.samples.push_back(
          Vec3(clean[0] + sigma * rng.gauss(), clean[1] + sigma * rng.gauss(), clean[2] + sigma * rng.gauss()));
    out.push_back(p);
  }
  return out;
}

CalibrationResult run(const std::vector<PositionSamples>& data, Modulus modulus, double magnitude) {
  CalibrationOptions o;
  o.modulus = modulus;
  o.magnitude = magnitude;
  return scalcal::calibrate(data, o);
}

// Without noise the norm modulus fixes bias and dk exactly (the axes have unit length, so A A^T
// gives (1 + dk)^2 on its diagonal); gamma equals phi_kj + phi_jk up to second order.
TEST(Estimator, NoiseFreeNormRecoversTheMeterExactly) {
  const double s = 1e-3;
  const TrueMeter m = example_meter(s, kG);
  const CalibrationResult r = run(bench(m, kG, 0, 1, 0, 1), Modulus::norm, kG);
  ASSERT_TRUE(r.summary.converged());
  EXPECT_LE(r.iterations, 10);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(r.bias(kG)(k), m.bias[k], 1e-12 * kG) << k;
    EXPECT_NEAR(r.X(3 + k), m.dk[k], 1e-12) << k;
    EXPECT_NEAR(r.X(6 + k), m.gamma()[k], 3 * s * s) << k;
  }
  EXPECT_LT(r.residual_rms, 1e-12 * kG);
}

// The rotation part of Phi moves the triad rigidly: two meters that differ only by it give the
// same estimates.
TEST(Estimator, RotationPartIsInvisible) {
  const double s = 1e-3;
  TrueMeter a = example_meter(s, 1.0), b = a;
  b.phi[0][1] += 0.7 * s;
  b.phi[1][0] -= 0.7 * s;
  b.phi[1][2] -= 0.4 * s;
  b.phi[2][1] += 0.4 * s;
  const CalibrationResult ra = run(bench(a, 1.0, 0, 1, 0, 1), Modulus::norm, 1.0);
  const CalibrationResult rb = run(bench(b, 1.0, 0, 1, 0, 1), Modulus::norm, 1.0);
  EXPECT_LT((ra.X - rb.X).cwiseAbs().maxCoeff(), 3 * s * s);
}

TEST(Estimator, NoisyRecoveryWithinFourStandardErrors) {
  const double s = 2e-3, sigma = 5e-3;  // sigma in m/s^2, |I| = g
  const int samples = 10;
  const TrueMeter m = example_meter(s, kG);
  for (Modulus mod : {Modulus::norm, Modulus::projection}) {
    const CalibrationResult r = run(bench(m, kG, sigma, samples, 0, 42), mod, kG);
    ASSERT_TRUE(r.summary.converged());
    ASSERT_EQ(r.noise_source, scalcal::NoiseSource::scatter);
    EXPECT_EQ(r.positions, 18);
    EXPECT_EQ(r.samples, 180);
    // The modulus of one sample carries eta.omega, of variance sigma^2; 162 degrees of freedom.
    EXPECT_NEAR(r.noise / sigma, 1.0, 0.2);
    // Standard errors: sigma/|I| sqrt(K(r,r)/samples), with K of the 18 positions (evaluate()).
    const scalcal::Evaluation ev = scalcal::evaluate(scalcal::Program::classic18());
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(r.X_std(k) / (sigma / kG * std::sqrt(ev.K(k, k) / samples)), 1.0, 0.2) << k;
    const double truth[9] = {m.bias[0] / kG, m.bias[1] / kG, m.bias[2] / kG, m.dk[0],     m.dk[1],
                             m.dk[2],        m.gamma()[0],   m.gamma()[1],   m.gamma()[2]};
    for (int k = 0; k < 9; ++k) EXPECT_LT(std::abs(r.X(k) - truth[k]), 4 * r.X_std(k)) << k;
  }
}

TEST(Estimator, NoiseFromResidualsWhenEachPositionHasOneSample) {
  const double sigma = 1e-4;
  const CalibrationResult r = run(bench(example_meter(1e-3, 1.0), 1.0, sigma, 1, 0, 7), Modulus::norm, 1.0);
  EXPECT_EQ(r.noise_source, scalcal::NoiseSource::residuals);
  EXPECT_NEAR(r.noise / sigma, 1.0, 0.6);  // only 18 - 9 = 9 degrees of freedom
}

// A tilt eps of the bench leaves m_I untouched, but m_II = I.eta_d loses cos(eps) ~ 1 - eps^2/2
// in every position; since x^2 + y^2 + z^2 = 1, a constant residual is absorbed by dk_x, dk_y,
// dk_z together: each is biased by -eps^2/2.
TEST(Estimator, BenchErrorBiasesOnlyTheProjectionModulus) {
  const double s = 1e-3, eps = 1.0 * M_PI / 180;
  const TrueMeter m = example_meter(s, 1.0);
  double norm_err = 0, proj_bias[3] = {0, 0, 0};
  const int runs = 20;
  for (int t = 0; t < runs; ++t) {
    const auto data = bench(m, 1.0, 0, 1, eps, 100 + t);
    const CalibrationResult n = run(data, Modulus::norm, 1.0);
    const CalibrationResult p = run(data, Modulus::projection, 1.0);
    for (int k = 0; k < 3; ++k) {
      norm_err = std::max(norm_err, std::abs(n.X(3 + k) - m.dk[k]));
      proj_bias[k] += (p.X(3 + k) - m.dk[k]) / runs;
    }
  }
  EXPECT_LT(norm_err, 1e-10);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(proj_bias[k], -eps * eps / 2, 0.2 * eps * eps / 2) << k;
}

}  // namespace

namespace {

// The estimator is written once for any scalar: in long double the noise-free recovery of bias
// and dk tightens from double's 1e-15 to long double's 1e-18.
TEST(Estimator, LongDoubleInstantiation) {
  using LD = long double;
  const calibration_test::TrueMeter m = calibration_test::example_meter(1e-3, 1.0);
  std::vector<scalcal::PositionSamplesTpl<LD>> data;
  for (const auto& e : calibration_test::classic18_positions()) {
    // The simulator is double; re-measure in long double through the library model, whose
    // conventions the double tests pin to the independent simulator.
    scalcal::MeterTpl<LD> meter;
    for (int k = 0; k < 3; ++k) {
      meter.bias(k) = m.bias[k];
      meter.scale_deviation(k) = m.dk[k];
      for (int j = 0; j < 3; ++j) meter.misalignment(k, j) = k == j ? 0 : m.phi[k][j];
    }
    scalcal::PositionSamplesTpl<LD> p;
    // normalised in long double: 1/sqrt2 rounded to double is off the unit sphere by 1e-16
    p.samples.push_back(meter.measure(scalcal::Vec3T<LD>(e[0], e[1], e[2]).normalized()));
    data.push_back(p);
  }
  scalcal::CalibrationOptionsTpl<LD> o;
  const auto r = scalcal::calibrate(data, o);
  ASSERT_TRUE(r.summary.converged());
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(std::abs(static_cast<double>(r.X(k) - LD(m.bias[k]))), 1e-17) << k;
    EXPECT_LT(std::abs(static_cast<double>(r.X(3 + k) - LD(m.dk[k]))), 1e-17) << k;
  }
}

}  // namespace
