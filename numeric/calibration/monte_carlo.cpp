// Monte-Carlo validation of the estimator on simulated meters (monte_carlo.hpp).
#include "numeric/calibration/monte_carlo.hpp"

#include "numeric/io/interrupt.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "numeric/calibration/model_calibration.hpp"
#include "numeric/criteria/model_evaluation.hpp"

namespace scalcal {

double MonteCarloResult::std_sampling_error() const {
  return converged > 1 ? 1.0 / std::sqrt(2.0 * (converged - 1)) : 0.0;
}

double MonteCarloResult::max_normalised_cov_difference() const {
  double worst = 0;
  for (Eigen::Index r = 0; r < theoretical_cov.rows(); ++r)
    for (Eigen::Index s = 0; s < theoretical_cov.cols(); ++s)
      worst = std::max(worst, std::abs(empirical_cov(r, s) - theoretical_cov(r, s)) /
                                  std::sqrt(theoretical_cov(r, r) * theoretical_cov(s, s)));
  return worst;
}

Meter reference_meter(double size) {
  Meter m;
  m.bias = size * Vec3(1.0, -0.5, 0.8);
  m.scale_deviation = size * Vec3(0.7, -1.2, 0.4);
  m.misalignment << 0.0, 0.6, -1.1,  //
      0.3, 0.0, -0.5,                //
      0.4, 0.9, 0.0;
  m.misalignment *= size;
  return m;
}

namespace {

// One data set of any meter with measure() (eq. 2, or a model's meter): each position tipped by
// the bench error, samples with noise.
template <class SomeMeter>
std::vector<PositionSamples> simulate_with(const SomeMeter& meter, const Program& nominal, double noise,
                                           double bench_error_deg, int samples, GaussianSource& rng) {
  std::vector<PositionSamples> data;
  const double angle = bench_error_deg * M_PI / 180.0;
  for (const Vec3& eta_nominal : nominal.positions) {
    PositionSamples p;
    p.nominal = eta_nominal;
    const Vec3 eta = angle > 0 ? tilt(eta_nominal, angle, rng.sampler()) : eta_nominal;
    const Vec3 clean = meter.measure(eta);  // |I| = 1
    for (int s = 0; s < samples; ++s) p.samples.push_back(clean + noise * Vec3(rng(), rng(), rng()));
    data.push_back(std::move(p));
  }
  return data;
}

struct Estimate {
  Eigen::VectorXd X;
  double noise = 0;
  Summary summary;  // the fit's own: a trial that did not converge is left out of the statistics
};

}  // namespace

std::vector<PositionSamples> simulate_measurements(const Meter& meter, const Program& nominal, double noise,
                                                   double bench_error_deg, int samples, GaussianSource& rng) {
  return simulate_with(meter, nominal, noise, bench_error_deg, samples, rng);
}

MonteCarloResult run_monte_carlo(const MonteCarloOptions& o, const std::function<void(int, int)>& progress,
                                 ModelKind model) {
  MonteCarloResult r;
  const bool paper9 = model_supports(model, ModelCapability::criteria_native);  // the meter is the paper's
  const Meter meter = reference_meter(o.size);
  const AnyMeter model_meter = paper9 ? AnyMeter(LinearMeter{meter}) : reference_model_meter(model, o.size);
  const MeterSlots slots = meter_slots(model);
  {
    const Eigen::VectorXd all = model_meter.parameters(1.0);
    r.truth.resize(static_cast<Eigen::Index>(slots.size()));
    for (std::size_t k = 0; k < slots.size(); ++k) r.truth(static_cast<Eigen::Index>(k)) = all(slots[k].index);
  }
  GaussianSource rng(o.seed);
  CalibrationOptions co;
  co.modulus = o.modulus;
  const auto simulate = [&](double noise, double bench, int samples, GaussianSource& g) {
    return paper9 ? simulate_with(meter, o.program, noise, bench, samples, g)
                  : simulate_with(model_meter, o.program, noise, bench, samples, g);
  };
  const auto estimate = [&](const std::vector<PositionSamples>& data) {
    Estimate e;
    if (paper9) {
      const CalibrationResult c = calibrate(data, co);
      e = {Eigen::VectorXd(c.X), c.noise, c.summary};
    } else {
      const ModelCalibration c = calibrate_model(model, data, co);
      e = {c.X, c.noise, c.summary};
    }
    return e;
  };
  {
    GaussianSource unused(0);
    r.noise_free = estimate(simulate(0.0, 0.0, 1, unused)).X;
  }
  std::vector<Eigen::VectorXd> estimates;
  double noise_ratio = 0, iterations = 0;
  for (int t = 0; t < o.trials; ++t) {
    check_interrupt();
    if (progress && (t % 100 == 0)) progress(t, o.trials);
    const Estimate c = estimate(simulate(o.noise, o.bench_error_deg, o.samples, rng));
    if (!c.summary.converged()) continue;
    estimates.push_back(c.X);
    noise_ratio += c.noise / o.noise;
    iterations += c.summary.iterations;
  }
  if (progress) progress(o.trials, o.trials);
  const Eigen::Index P = r.truth.size();
  r.converged = static_cast<int>(estimates.size());
  r.mean = Eigen::VectorXd::Zero(P);
  for (const auto& e : estimates) r.mean += e;
  r.empirical_cov = Eigen::MatrixXd::Zero(P, P);
  if (r.converged > 0) {
    r.mean /= r.converged;
    r.mean_noise_ratio = noise_ratio / r.converged;
    r.mean_iterations = iterations / r.converged;
  }
  for (const auto& e : estimates) r.empirical_cov += (e - r.mean) * (e - r.mean).transpose();
  if (r.converged > 1) r.empirical_cov /= (r.converged - 1);

  const ModelEvaluation ev = evaluate(model, o.program);
  r.names = ev.parameter_names;
  r.theoretical_cov = o.noise * o.noise / o.samples * ev.K;
  const double N = o.program.size();
  for (int q = 0; q < 4; ++q) {
    r.theta_theoretical(q) = ev.theta[static_cast<std::size_t>(q)];
    double v = -1;
    for (Eigen::Index k = 0; k < P; ++k)
      if (static_cast<int>(ev.parameter_groups[static_cast<std::size_t>(k)]) == q)
        v = std::max(v, r.empirical_cov(k, k));
    r.theta_empirical(q) = v < 0 ? std::numeric_limits<double>::quiet_NaN() : std::sqrt(N * o.samples * v) / o.noise;
  }
  return r;
}

}  // namespace scalcal
