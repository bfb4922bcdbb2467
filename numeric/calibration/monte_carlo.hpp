// Monte-Carlo validation of the estimator: calibrate many simulated meters (eq. 2 with noise and
// bench errors) and compare the empirical covariance of the estimates with sigma^2 K, the theory
// behind every criterion of the paper.
#pragma once
#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "numeric/calibration/meter_model.hpp"
#include "numeric/calibration/scalar_calibration.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

struct MonteCarloOptions {
  Program program;
  int trials = 1000;
  double noise = 1e-4;           // sigma of each axis' noise, in units of |I|
  double bench_error_deg = 0.0;  // every true position is the nominal one tipped by this angle
  Modulus modulus = Modulus::norm;
  std::uint64_t seed = 1;
  int samples = 1;     // samples per position
  double size = 1e-3;  // scale of the simulated meter's errors (see reference_meter)
};

// P entries for a model of P parameters (9 for the paper's), in the model's order.
struct MonteCarloResult {
  std::vector<std::string_view> names;  // the model's parameter names
  Eigen::VectorXd truth;                // X of the simulated meter (gamma = phi_kj + phi_jk)
  Eigen::VectorXd mean;                 // mean estimate over the converged trials
  // The estimate from noise-free data without bench errors: truth + the error of the first-order
  // model itself (second order in the meter's errors), the value the noisy estimates scatter about.
  Eigen::VectorXd noise_free;
  Eigen::MatrixXd empirical_cov;    // covariance of the estimates about their mean
  Eigen::MatrixXd theoretical_cov;  // sigma^2 K / samples
  // sqrt(N max_r var_r) / sigma per group (bias, scale, nonorth, cubic; NaN for a group the model
  // lacks), and the same from K: theta_q of evaluate().
  Eigen::Vector4d theta_empirical, theta_theoretical;
  double mean_noise_ratio = 0;  // mean over trials of the estimated noise / sigma
  int converged = 0;            // trials whose iteration converged (only these are counted)
  double mean_iterations = 0;

  // Relative standard error of an empirical standard deviation from n Gaussian samples.
  double std_sampling_error() const;
  // Largest |C_emp(r,s) - C_th(r,s)| / sqrt(C_th(r,r) C_th(s,s)): about 1/sqrt(T) when K holds.
  double max_normalised_cov_difference() const;
};

// The simulated meter: a fixed pattern of errors with every component about `size`, including a
// rotation part of Phi that scalar calibration must not see.
Meter reference_meter(double size);

// One simulated data set: each position tipped by the bench error, samples with noise.
std::vector<PositionSamples> simulate_measurements(const Meter& meter, const Program& nominal, double noise,
                                                   double bench_error_deg, int samples, GaussianSource& rng);

// `progress(done, total)` is called now and then (may be empty). The paper's model by default;
// another model's meter is reference_model_meter (numeric/calibration/model_calibration.hpp),
// calibrated by calibrate_model.
MonteCarloResult run_monte_carlo(const MonteCarloOptions& options, const std::function<void(int, int)>& progress = {},
                                 ModelKind model = ModelKind::paper9);

}  // namespace scalcal
