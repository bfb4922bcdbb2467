// The noise bias of a single-sample fit (noise_bias.hpp).
#include "numeric/calibration/noise_bias.hpp"

#include <Eigen/Cholesky>

#include "numeric/calibration/meter_model.hpp"

namespace scalcal {

NoiseBias estimate_noise_bias(ModelKind model, const std::vector<PositionSamples>& data,
                              const CalibrationOptions& options, const ModelCalibration& fit, const Mat3& sample_noise,
                              std::uint64_t seed, int replicates) {
  NoiseBias out;
  if (sample_noise.isZero() || !fit.summary.converged() || replicates < 1) return out;
  const Eigen::LLT<Mat3> chol(sample_noise);
  if (chol.info() != Eigen::Success) return out;
  // The copies are made in the corrected frame, where the fitted meter is the identity: each refit
  // then starts where the estimate stands as the fit itself started near it (the estimator is the
  // paper's fixed point, reached from near it; from far, the iteration ends at the least-squares
  // minimum instead, whose common scale differs by the noise's square). The noise is mapped there by
  // the correction's linear part; X near zero composes with the estimate additively to first order.
  const Mat3 C = fit.meter.linear().gain().inverse();
  const Mat3 L = C * Mat3(chol.matrixL());
  // Where the fit puts each sample: the corrected vector's direction, at the field's magnitude.
  std::vector<Vec3> truth;
  truth.reserve(data.size());
  for (const auto& p : data)
    for (const auto& s : p.samples) truth.push_back(options.magnitude * fit.meter.compensate(s).normalized());
  // Antithetic pairs: each draw of the noise is used as it is and negated. The estimate's response
  // to the noise is odd to first order and even at the second, the bias: the pair's mean keeps the
  // second and cancels the first, whose scatter (a standard error per copy) would otherwise enter the
  // correction as a quarter of a standard error at 16 copies. Only pairs that both converge count.
  GaussianSource gauss(seed);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(fit.X.size());
  std::vector<PositionSamples> copy = data;
  std::vector<Vec3> noise(truth.size());
  for (int k = 0; k + 1 < replicates; k += 2) {
    for (auto& e : noise) e = L * Vec3(gauss(), gauss(), gauss());
    Eigen::VectorXd pair = Eigen::VectorXd::Zero(fit.X.size());
    bool both = true;
    for (const double sign : {1.0, -1.0}) {
      std::size_t t = 0;
      for (auto& p : copy)
        for (auto& s : p.samples) {
          s = truth[t] + sign * noise[t];
          ++t;
        }
      const ModelCalibration again = calibrate_model(model, copy, options);
      both = both && again.summary.converged() && again.X.allFinite();
      if (both) pair += again.X;
    }
    if (!both) continue;
    sum += pair;
    out.replicates += 2;
  }
  if (out.replicates > 0) out.bias = sum / out.replicates;
  return out;
}

void remove_noise_bias(ModelCalibration& fit, const NoiseBias& bias, double magnitude) {
  if (bias.bias.size() != fit.X.size()) return;
  fit.X -= bias.bias;
  fit.meter = model_meter(fit.model, fit.X, magnitude);
}

}  // namespace scalcal
