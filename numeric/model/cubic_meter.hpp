// cubic12's meter: eq. (2) plus a quadratic output term per axis, c_i a_i^2 on axis i (a = Phi I: a scale factor
// linear in the input), whose modulus term is c_i |I| eta_i^3; so at one magnitude c_i |I| is what is identified.
#pragma once
#include <array>
#include <string_view>

#include <Eigen/Core>

#include "numeric/model/linear_meter.hpp"
#include "numeric/model/meter.hpp"
#include "numeric/model/model.hpp"

namespace scalcal {

struct CubicMeter {
  Meter linear;
  Vec3 cubic = Vec3::Zero();  // c_i, in 1 / (units of I)

  // The linear meter's nine, then cubic_x, cubic_y, cubic_z.
  static constexpr std::array<MeterParameter, 12> kParameters = [] {
    std::array<MeterParameter, 12> out{};
    for (std::size_t k = 0; k < LinearMeter::kParameters.size(); ++k) out[k] = LinearMeter::kParameters[k];
    out[9] = {"cubic_x", ParameterGroup::cubic, 0};
    out[10] = {"cubic_y", ParameterGroup::cubic, 1};
    out[11] = {"cubic_z", ParameterGroup::cubic, 2};
    return out;
  }();
  // All groups but the cubic terms keep the correction physical = matrix (raw - offset); those make each axis'
  // output a quadratic in its input.
  static constexpr bool linear_group(ParameterGroup g) { return g != ParameterGroup::cubic; }
  // Why a fit of those needs data in the field's units (calibrate's refusal of data in other units).
  static constexpr std::string_view units_bound = "its cubic term is relative to |I|";

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
