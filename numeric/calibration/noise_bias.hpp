// The bias a fit of single noisy samples carries, and its removal by refitting simulated copies.
// Fitting |C (m - o)| = |I| to samples whose noise is a few percent of the field (a tumbling
// magnetometer's: the public QMC5883L log's is 5.6 %) biases the estimate by terms of the order of
// the noise's square, more along some axes than others: 0.3 to 1.2 % of a gain, 5 to 10 standard
// errors, on rehearsals of that log (embedded/tests/anisotropic_noise.py), the independent SciPy fit
// alike. The bias is a smooth function of the meter, the directions and the noise, so it is estimated
// where the fit stands (a parametric bootstrap): copies of the data at the fitted directions, with the
// log's own noise (second differences) through the correction, are refitted, and the mean of their
// estimates is the bias to take off.
#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "numeric/calibration/model_calibration.hpp"
#include "numeric/calibration/scalar_calibration.hpp"

namespace scalcal {

// Simulated copies refitted, in antithetic pairs (noise_bias.cpp): the bias's own Monte Carlo error
// is then of the order of the bias over 4, not of the standard error over 4.
inline constexpr int kNoiseBiasReplicates = 16;

struct NoiseBias {
  Eigen::VectorXd bias;  // mean refit about the estimate, the estimator's units (model order); empty when none
  int replicates = 0;    // refits that converged (a pair of copies of which one does not is left out)
};

// `fit` was fitted to `data` with `options`; `sample_noise` is one sample's noise covariance in the
// units of the data. Deterministic for a seed.
NoiseBias estimate_noise_bias(ModelKind model, const std::vector<PositionSamples>& data,
                              const CalibrationOptions& options, const ModelCalibration& fit, const Mat3& sample_noise,
                              std::uint64_t seed, int replicates = kNoiseBiasReplicates);

// The estimate with `bias` taken off: X, and the meter it stands for.
void remove_noise_bias(ModelCalibration& fit, const NoiseBias& bias, double magnitude);

}  // namespace scalcal
