// cubic12's meter: eq. (2) plus a quadratic output term per axis, c_i a_i^2 on axis i (a = Phi I: a scale factor
// linear in the input), whose modulus term is c_i |I| eta_i^3; so at one magnitude c_i |I| is what is identified.
#pragma once
#include <array>

#include <Eigen/Core>

#include "numeric/model/meter.hpp"
#include "numeric/model/model.hpp"

namespace scalcal {

struct CubicMeter {
  Meter linear;
  Vec3 cubic = Vec3::Zero();  // c_i, in 1 / (units of I)

  static constexpr std::array<MeterParameter, 12> kParameters = {{{"bias_x", ParameterGroup::bias, 0},
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
  // All groups but the cubic terms keep the correction physical = matrix (raw - offset); those make each axis'
  // output a quadratic in its input.
  static constexpr bool linear_group(ParameterGroup g) { return g != ParameterGroup::cubic; }

  Vec3 measure(const Vec3& I) const;
  // The I that would have produced `measured` (each axis' quadratic solved for its root near the linear one);
  // NaN entries when the quadratic has no real root.
  Vec3 compensate(const Vec3& measured) const;
  // All twelve, in kParameters order.
  Eigen::Matrix<double, 12, 1> parameters(double magnitude) const;
  static CubicMeter from_parameters(const Eigen::Matrix<double, 12, 1>& X, double magnitude);
  // The meter `simulate --model` draws from: the reference linear part and cubic terms of the same size.
  static CubicMeter reference(const Meter& linear, double size) { return {linear, size * Vec3(0.9, -0.6, 1.3)}; }
};
static_assert(CalibrationMeter<CubicMeter>);

}  // namespace scalcal
