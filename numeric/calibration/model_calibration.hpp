// Scalar calibration for a model other than the paper's (--model on calibrate and simulate): the
// same iteration (eqs. 3-6) with the model's design row, and the model's own meter (its `meter` type,
// numeric/model/linear_meter.hpp, cubic_meter.hpp) with only the model's parameters set.
#pragma once
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "numeric/calibration/meter_model.hpp"
#include "numeric/calibration/scalar_calibration.hpp"
#include "numeric/model/any_meter.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

// Where each of the model's parameters is among its meter's, found by name when the model is compiled: a model
// naming a parameter its meter does not know does not compile (the throw ends constant evaluation).
template <class Model>
consteval std::array<int, Model::kParameters> meter_index_of() {
  constexpr auto& known = Model::meter::kParameters;
  std::array<int, Model::kParameters> out{};
  for (std::size_t k = 0; k < out.size(); ++k) {
    std::size_t m = 0;
    while (m < known.size() && known[m].name != Model::parameter_names[k]) ++m;
    if (m == known.size()) throw "a model parameter the meter does not know";
    out[k] = static_cast<int>(m);
  }
  return out;
}

// One of a model's parameters as its meter knows it: its index among the meter's parameters, its name, group and
// axis, and whether it keeps the correction physical = matrix (raw - offset).
struct MeterSlot {
  int index;
  MeterParameter parameter;
  bool linear;
};
using MeterSlots = std::vector<MeterSlot>;

// The model's parameters, in its order, as its meter knows them.
MeterSlots meter_slots(ModelKind model);

// The positions among the model's parameters of its meter's group g, by axis: all three, or none when the model
// lacks any of them.
std::vector<int> meter_group(const MeterSlots& slots, ParameterGroup g);
bool has_meter_group(const MeterSlots& slots, ParameterGroup g);
// Whether the model's correction is physical = matrix (raw - offset): each of its parameters in a linear group of
// its meter.
bool corrects_linearly(const MeterSlots& slots);
// Why a model that does not correct linearly calibrates data in the field's units only: its meter's `units_bound`
// sentence ("its cubic term is relative to |I|"), or a general one when the meter states none.
std::string_view meter_units_bound(ModelKind model);

// The meter that the model's parameters X (estimator units, at the field's magnitude) stand for; its meter's
// parameters outside the model are zero.
AnyMeter model_meter(ModelKind model, const Eigen::VectorXd& X, double magnitude);

struct ModelCalibration {
  ModelKind model = ModelKind::paper9;
  Eigen::VectorXd X, X_std;  // P entries, estimator units
  Eigen::MatrixXd K;         // (H^T W H)^-1 at the estimate
  double noise = 0, residual_rms = 0;
  NoiseSource noise_source = NoiseSource::none;
  int iterations = 0, positions = 0, samples = 0;
  Summary summary;  // converged, or why not
  AnyMeter meter;   // the estimate as the model's meter (its parameters outside the model are zero)
};

// Preconditions as calibrate(): rank P of the model at the positions' directions, nominal
// directions for the projection modulus.
ModelCalibration calibrate_model(ModelKind model, const std::vector<PositionSamples>& data,
                                 const CalibrationOptions& options);

// The simulated meter of `simulate --model`: reference_meter's pattern with only the model's
// parameters (a misalignment without non-orthogonality keeps its rotation part, which no scalar
// calibration sees), and cubic terms of the same size for cubic12.
AnyMeter reference_model_meter(ModelKind model, double size);

}  // namespace scalcal
