// Offsets only, h(eta) = (x, y, z): the magnetometer calibration of a vehicle that cannot be turned
// far (ArduPilot, PX4). trace M = N for unit vectors fixes every limit (proofs/bias3_limits.md).
#pragma once
#include "numeric/model/linear_meter.hpp"
#include "numeric/model/model_limit.hpp"
#include "numeric/model/monomial_model.hpp"

namespace scalcal {

struct Bias3Model : MonomialModel<Bias3Model> {
  static constexpr int kParameters = 3;
  static constexpr std::string_view name = "bias3";
  using meter = LinearMeter;  // its parameters are this meter's, by name
  static constexpr std::string_view summary = "h = (x, y, z): offsets only";
  // What a fit under this model leaves out beyond the rotation no scalar calibration sees (calibrate's report).
  static constexpr std::string_view not_estimated =
      "the scale factors are taken as equal (one gain, from the start) and the axes as orthogonal: their errors go "
      "into the residual";
  static constexpr std::array<std::string_view, 3> parameter_names = {"bias_x", "bias_y", "bias_z"};
  static constexpr std::array<ParameterGroup, 3> parameter_groups = {ParameterGroup::bias, ParameterGroup::bias,
                                                                     ParameterGroup::bias};
  static constexpr std::array<Exponents, 3> exponents = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

  static constexpr bool auto_choice = true;   // --model auto may choose it
  static constexpr bool thermal_base = true;  // bias3+Tk: the offsets drift (what PX4 and ArduPilot fit)
  static constexpr std::string_view proof = "proofs/bias3_limits.md";
  static constexpr std::string_view tight = "sum eta eta^T = (N/3) I (a unit-norm tight frame): every N >= 3 (proven)";
  static constexpr std::array<ModelLimit, 4> limits = {{
      {"D", 27.0, "27", "", "", "", kNotDetermined, "any measure with E[eta eta^T] = I/3", tight},
      {"A", 9.0, "9", "", "", "", kNotDetermined, "any measure with E[eta eta^T] = I/3", tight},
      {"E", 3.0, "3", "", "", "", kNotDetermined, "any measure with E[eta eta^T] = I/3", tight},
      {"S", 3.0, "3", "", "", "", kNotDetermined, "any measure with E[eta eta^T] = I/3", tight},
  }};
};
static_assert(CalibrationModel<Bias3Model>);

}  // namespace scalcal
