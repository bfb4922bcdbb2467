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

// Eq. (2) plus the per-axis quadratic output term.
struct ModelMeter {
  Meter linear;
  Vec3 cubic = Vec3::Zero();  // c_i, in 1 / (units of I)

  // A parameter the meter knows, in the estimator's units (bias / |I|, dk, gamma, c |I|): its name, its
  // group and its axis (a non-orthogonality's first axis: xy 0, yz 1, zx 2).
  struct Parameter {
    std::string_view name;
    ParameterGroup group;
    int axis;
  };
  static constexpr std::array<Parameter, 12> kParameters = {{{"bias_x", ParameterGroup::bias, 0},
                                                             {"bias_y", ParameterGroup::bias, 1},
                                                             {"bias_z", ParameterGroup::bias, 2},
                                                             {"scale_x", ParameterGroup::scale, 0},
                                                             {"scale_y", ParameterGroup::scale, 1},
                                                             {"scale_z", ParameterGroup::scale, 2},
                                                             {"nonorth_xy", ParameterGroup::nonorth, 0},
                                                             {"nonorth_yz", ParameterGroup::nonorth, 1},
                                                             {"nonorth_zx", ParameterGroup::nonorth, 2},
                                                             {"cubic_x", ParameterGroup::cubic, 0},
                                                             {"cubic_y", ParameterGroup::cubic, 1},
                                                             {"cubic_z", ParameterGroup::cubic, 2}}};
  // Whether a group's parameters keep the correction physical = matrix (raw - offset): all but the cubic
  // terms, which make each axis' output a quadratic in its input.
  static constexpr bool linear_group(ParameterGroup g) { return g != ParameterGroup::cubic; }

  Vec3 measure(const Vec3& I) const;
  // The I that would have produced `measured` (each axis' quadratic solved for its root near the
  // linear one); NaN entries when the quadratic has no real root.
  Vec3 compensate(const Vec3& measured) const;
  // All twelve, in kParameters order.
  Eigen::Matrix<double, 12, 1> parameters(double magnitude) const;
  static ModelMeter from_parameters(const Eigen::Matrix<double, 12, 1>& X, double magnitude);
};

// Where each of the model's parameters is among the meter's, found by name when the model is compiled: a
// model naming a parameter the meter does not know does not compile (the throw ends constant evaluation).
template <class Model>
consteval std::array<int, Model::kParameters> meter_index_of() {
  std::array<int, Model::kParameters> out{};
  for (std::size_t k = 0; k < out.size(); ++k) {
    std::size_t m = 0;
    while (m < ModelMeter::kParameters.size() && ModelMeter::kParameters[m].name != Model::parameter_names[k]) ++m;
    if (m == ModelMeter::kParameters.size()) throw "a model parameter the meter does not know";
    out[k] = static_cast<int>(m);
  }
  return out;
}

// meter_index_of for the model behind a ModelKind.
std::vector<int> meter_indices(ModelKind model);

// The positions among the model's parameters (meter indices `index`) of the meter's group g, by axis: all three,
// or none when the model lacks any of them.
std::vector<int> meter_group(const std::vector<int>& index, ParameterGroup g);
bool has_meter_group(const std::vector<int>& index, ParameterGroup g);
// Whether the model's correction is physical = matrix (raw - offset): none of its parameters outside the
// meter's linear groups.
bool corrects_linearly(const std::vector<int>& index);

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
