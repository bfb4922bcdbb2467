// Bias and scale factor, no non-orthogonality: h(eta) = (x, y, z, x^2, y^2, z^2), the axis-aligned
// ellipsoid that ArduPilot and PX4 fit first. trace M = 1 + E[x^4 + y^4 + z^4] <= 2 fixes every
// limit, and only the six-position test reaches it (proofs/axis6_limits.md).
#pragma once
#include "numeric/model/linear_meter.hpp"
#include "numeric/model/model_limit.hpp"
#include "numeric/model/monomial_model.hpp"

namespace scalcal {

struct Axis6Model : MonomialModel<Axis6Model> {
  static constexpr int kParameters = 6;
  static constexpr std::string_view name = "axis6";
  using meter = LinearMeter;  // its parameters are this meter's, by name
  static constexpr std::string_view summary = "h = (x, y, z, x^2, y^2, z^2): bias and scale factor";
  // What a fit under this model leaves out beyond the rotation no scalar calibration sees (calibrate's report).
  static constexpr std::string_view not_estimated =
      "the axes are taken as orthogonal: non-orthogonality goes into the residual";
  static constexpr std::array<std::string_view, 6> parameter_names = {"bias_x",  "bias_y",  "bias_z",
                                                                      "scale_x", "scale_y", "scale_z"};
  static constexpr std::array<ParameterGroup, 6> parameter_groups = {ParameterGroup::bias,  ParameterGroup::bias,
                                                                     ParameterGroup::bias,  ParameterGroup::scale,
                                                                     ParameterGroup::scale, ParameterGroup::scale};
  static constexpr std::array<Exponents, 6> exponents = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}}};

  static constexpr bool auto_choice = true;   // --model auto may choose it
  static constexpr bool thermal_base = true;  // axis6+Tk: bias and scale factor drift with temperature
  static constexpr std::string_view proof = "proofs/axis6_limits.md";
  static constexpr std::string_view six = "the six axis directions +-x, +-y, +-z, each N/6 times";
  static constexpr std::string_view only = "exactly N = 6k, by the six axis directions k times each (proven)";
  static constexpr std::array<ModelLimit, 4> limits = {{
      {"D", 729.0, "729", "1/3", "0", "", 0.0, six, only, 1.0},
      {"A", 18.0, "18", "1/3", "0", "", 0.0, six, only, 1.0},
      {"E", 3.0, "3", "1/3", "0", "", 0.0, six, only, 1.0},
      {"S", 3.0, "3", "1/3", "0", "", 0.0, six, only, 1.0},
  }};
};
static_assert(CalibrationModel<Axis6Model>);

}  // namespace scalcal
