// The meter of the linear models (paper9, axis6, bias3): eq. (2) and nothing more, as the scalar estimator sees it,
// with 9 parameters (bias / |I|, dk, gamma); a model with fewer names the ones it estimates among these.
#pragma once
#include <array>

#include "numeric/model/meter.hpp"
#include "numeric/model/model.hpp"

namespace scalcal {

struct LinearMeter {
  Meter linear;

  static constexpr std::array<MeterParameter, 9> kParameters = {{{"bias_x", ParameterGroup::bias, 0},
                                                                 {"bias_y", ParameterGroup::bias, 1},
                                                                 {"bias_z", ParameterGroup::bias, 2},
                                                                 {"scale_x", ParameterGroup::scale, 0},
                                                                 {"scale_y", ParameterGroup::scale, 1},
                                                                 {"scale_z", ParameterGroup::scale, 2},
                                                                 {"nonorth_xy", ParameterGroup::nonorth, 0},
                                                                 {"nonorth_yz", ParameterGroup::nonorth, 1},
                                                                 {"nonorth_zx", ParameterGroup::nonorth, 2}}};
  // Every group keeps the correction physical = matrix (raw - offset).
  static constexpr bool linear_group(ParameterGroup) { return true; }

  // Axis by axis: the input's projection a = Phi I, then a_i (1 + dk_i) + Delta_i; compensate undoes the two
  // in turn. Meter::compensate inverts the gain (E + dK) Phi as one matrix instead, which rounds differently:
  // this is the form the estimator has always used, and the cubic meter's at c = 0.
  Vec3 measure(const Vec3& I) const;
  Vec3 compensate(const Vec3& measured) const;
  Vec9T<double> parameters(double magnitude) const { return linear.parameters(magnitude); }
  static LinearMeter from_parameters(const Vec9T<double>& X, double magnitude) {
    return {Meter::from_parameters(X, magnitude)};
  }
  // The meter `simulate --model` draws from: the reference meter's linear part is all there is.
  static LinearMeter reference(const Meter& linear, double /*size*/) { return {linear}; }
};
static_assert(CalibrationMeter<LinearMeter>);

}  // namespace scalcal
