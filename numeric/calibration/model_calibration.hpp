// Scalar calibration for a model other than the paper's (--model on calibrate and simulate): the
// same iteration (eqs. 3-6) with the model's design row, and a meter that has only the model's
// parameters. cubic12's meter adds c_i a_i^2 to axis i (a = Phi I: a scale factor linear in the
// input), whose modulus term is c_i |I| eta_i^3; so at one magnitude c_i |I| is what is identified.
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "numeric/calibration/meter_model.hpp"
#include "numeric/calibration/scalar_calibration.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

// The parameters a meter knows, in the estimator's units: bias / |I|, dk, gamma, c |I|.
inline constexpr std::array<std::string_view, 12> kMeterParameterNames = {
    "bias_x",     "bias_y",     "bias_z",     "scale_x", "scale_y", "scale_z",
    "nonorth_xy", "nonorth_yz", "nonorth_zx", "cubic_x", "cubic_y", "cubic_z"};

// Eq. (2) plus the per-axis quadratic output term.
struct ModelMeter {
  Meter linear;
  Vec3 cubic = Vec3::Zero();  // c_i, in 1 / (units of I)

  Vec3 measure(const Vec3& I) const;
  // The I that would have produced `measured` (each axis' quadratic solved for its root near the
  // linear one); NaN entries when the quadratic has no real root.
  Vec3 compensate(const Vec3& measured) const;
  // All twelve, in kMeterParameterNames order.
  Eigen::Matrix<double, 12, 1> parameters(double magnitude) const;
  static ModelMeter from_parameters(const Eigen::Matrix<double, 12, 1>& X, double magnitude);
};

// Index into kMeterParameterNames of each of the model's parameters. Throws std::invalid_argument
// naming a parameter the meter does not know.
std::vector<int> meter_indices(ModelKind model);

struct ModelCalibration {
  ModelKind model = ModelKind::paper9;
  Eigen::VectorXd X, X_std;  // P entries, estimator units
  Eigen::MatrixXd K;         // (H^T W H)^-1 at the estimate
  double noise = 0, residual_rms = 0;
  NoiseSource noise_source = NoiseSource::none;
  int iterations = 0, positions = 0, samples = 0;
  Summary summary;   // converged, or why not
  ModelMeter meter;  // the estimate as a meter (parameters outside the model are zero)
};

// Preconditions as calibrate(): rank P of the model at the positions' directions, nominal
// directions for the projection modulus.
ModelCalibration calibrate_model(ModelKind model, const std::vector<PositionSamples>& data,
                                 const CalibrationOptions& options);

// The simulated meter of `simulate --model`: reference_meter's pattern with only the model's
// parameters (a misalignment without non-orthogonality keeps its rotation part, which no scalar
// calibration sees), and cubic terms of the same size for cubic12.
ModelMeter reference_model_meter(ModelKind model, double size);

}  // namespace scalcal
