#include "numeric/calibration/monte_carlo.hpp"

#include <cmath>

#include "numeric/criteria/evaluation.hpp"

namespace scalcal {

double MonteCarloResult::std_sampling_error() const {
  return converged > 1 ? 1.0 / std::sqrt(2.0 * (converged - 1)) : 0.0;
}

double MonteCarloResult::max_normalised_cov_difference() const {
  double worst = 0;
  for (int r = 0; r < 9; ++r)
    for (int s = 0; s < 9; ++s)
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

std::vector<PositionSamples> simulate_measurements(const Meter& meter, const Program& nominal, double noise,
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

MonteCarloResult run_monte_carlo(const MonteCarloOptions& o, const std::function<void(int, int)>& progress) {
  MonteCarloResult r;
  const Meter meter = reference_meter(o.size);
  r.truth = meter.parameters(1.0);
  GaussianSource rng(o.seed);
  CalibrationOptions co;
  co.modulus = o.modulus;
  {
    GaussianSource unused(0);
    r.noise_free = calibrate(simulate_measurements(meter, o.program, 0.0, 0.0, 1, unused), co).X;
  }
  std::vector<Vec9> estimates;
  double noise_ratio = 0, iterations = 0;
  for (int t = 0; t < o.trials; ++t) {
    if (progress && (t % 100 == 0)) progress(t, o.trials);
    const auto data = simulate_measurements(meter, o.program, o.noise, o.bench_error_deg, o.samples, rng);
    const CalibrationResult c = calibrate(data, co);
    if (!c.converged) continue;
    estimates.push_back(c.X);
    noise_ratio += c.noise / o.noise;
    iterations += c.iterations;
  }
  if (progress) progress(o.trials, o.trials);
  r.converged = static_cast<int>(estimates.size());
  r.mean.setZero();
  for (const auto& e : estimates) r.mean += e;
  r.empirical_cov.setZero();
  if (r.converged > 0) {
    r.mean /= r.converged;
    r.mean_noise_ratio = noise_ratio / r.converged;
    r.mean_iterations = iterations / r.converged;
  }
  for (const auto& e : estimates) r.empirical_cov += (e - r.mean) * (e - r.mean).transpose();
  if (r.converged > 1) r.empirical_cov /= (r.converged - 1);

  const Evaluation ev = evaluate(o.program);
  r.theoretical_cov = o.noise * o.noise / o.samples * ev.K;
  r.theta_theoretical = Vec3(ev.theta_bias, ev.theta_scale, ev.theta_nonorth);
  const double N = o.program.size();
  for (int q = 0; q < 3; ++q) {
    const double v = r.empirical_cov.diagonal().segment<3>(3 * q).maxCoeff();
    r.theta_empirical(q) = std::sqrt(N * o.samples * v) / o.noise;
  }
  return r;
}

}  // namespace scalcal
