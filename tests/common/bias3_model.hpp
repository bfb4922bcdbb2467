// A second model, defined in this one file only to show that a new model needs nothing else:
// offsets only, h(eta) = (x, y, z) (the magnetometer "offsets-only" calibration). Its limits follow
// by hand from trace M = N for unit vectors: D = N^3 / det M >= 27, A = N tr K >= 9, E >= 3 and
// S >= 3, all with equality exactly when M = (N/3) I (e.g. the six axis positions).
#pragma once
#include "numeric/model/model.hpp"

namespace scalcal::testing {

struct Bias3Model {
  static constexpr int kParameters = 3;
  static constexpr std::string_view name = "bias3";
  static constexpr std::array<std::string_view, 3> parameter_names = {"bias_x", "bias_y", "bias_z"};
  static constexpr std::array<ParameterGroup, 3> parameter_groups = {ParameterGroup::bias, ParameterGroup::bias,
                                                                      ParameterGroup::bias};

  template <class Scalar>
  static RowT<Bias3Model, Scalar> row(const Vec3T<Scalar>& e) {
    return e;
  }
  template <class Scalar>
  static JacobianT<Bias3Model, Scalar> jacobian(const Vec3T<Scalar>&) {
    return JacobianT<Bias3Model, Scalar>::Identity();
  }
  template <class Scalar>
  static Mat3T<Scalar> curvature(const RowT<Bias3Model, Scalar>&) {
    return Mat3T<Scalar>::Zero();
  }
};
static_assert(CalibrationModel<Bias3Model>);

}  // namespace scalcal::testing
