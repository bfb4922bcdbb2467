// The paper's model (eq. 5): nine parameters X = (bias, scale-factor deviation, non-orthogonality),
// h(eta) = (x, y, z, x^2, y^2, z^2, xy, yz, zx). The model every command uses by default.
#pragma once
#include "numeric/model/linear_meter.hpp"
#include "numeric/model/model.hpp"

namespace scalcal {

struct Paper9Model {
  static constexpr int kParameters = 9;
  static constexpr std::string_view name = "paper9";
  using meter = LinearMeter;  // its parameters are this meter's, by name
  static constexpr std::string_view summary = "h = (x, y, z, x^2, y^2, z^2, xy, yz, zx): the paper's model";
  // Its limits come from the criteria and symbolic/limits.hpp, proven here:
  static constexpr std::string_view proof = "proofs/d_limit.md, proofs/aes_limits.md";
  // Capabilities (registry.hpp, model_supports): the criteria's exact limits and kernels, the region machinery,
  // the MPFR polish are written for the paper's rows; thermal models drift its meter (eq. 2), as axis6's and bias3's.
  static constexpr bool criteria_native = true;
  static constexpr bool region_limits = true;
  static constexpr bool polish_digits = true;
  static constexpr bool thermal_base = true;
  static constexpr bool auto_choice = true;
  static constexpr std::array<std::string_view, 9> parameter_names = {
      "bias_x", "bias_y", "bias_z", "scale_x", "scale_y", "scale_z", "nonorth_xy", "nonorth_yz", "nonorth_zx"};
  static constexpr std::array<ParameterGroup, 9> parameter_groups = {
      ParameterGroup::bias,    ParameterGroup::bias,    ParameterGroup::bias,
      ParameterGroup::scale,   ParameterGroup::scale,   ParameterGroup::scale,
      ParameterGroup::nonorth, ParameterGroup::nonorth, ParameterGroup::nonorth};

  template <class Scalar>
  static RowT<Paper9Model, Scalar> row(const Vec3T<Scalar>& e) {
    RowT<Paper9Model, Scalar> h;
    h << e(0), e(1), e(2), e(0) * e(0), e(1) * e(1), e(2) * e(2), e(0) * e(1), e(1) * e(2), e(2) * e(0);
    return h;
  }

  template <class Scalar>
  static JacobianT<Paper9Model, Scalar> jacobian(const Vec3T<Scalar>& e) {
    const Scalar zero(0), one(1), two(2);
    JacobianT<Paper9Model, Scalar> J;
    J << one, zero, zero, zero, one, zero, zero, zero, one, two * e(0), zero, zero, zero, two * e(1), zero, zero, zero,
        two * e(2), e(1), e(0), zero, zero, e(2), e(1), e(2), zero, e(0);
    return J;
  }

  // Only the quadratic rows curve: d^2(x^2) = 2 e_x e_x^T, d^2(xy) = e_x e_y^T + e_y e_x^T, ...
  template <class Scalar>
  static Mat3T<Scalar> curvature(const RowT<Paper9Model, Scalar>& w, const Vec3T<Scalar>& /*at*/) {
    const Scalar two(2);
    Mat3T<Scalar> T;
    T << two * w(3), w(6), w(8), w(6), two * w(4), w(7), w(8), w(7), two * w(5);
    return T;
  }
};
static_assert(CalibrationModel<Paper9Model>);

// The paper's model under the names the calibration and the CLI have always used.
inline constexpr int kParameters = Paper9Model::kParameters;
inline constexpr auto kParameterNames = Paper9Model::parameter_names;

template <class Scalar>
using Mat9T = InformationT<Paper9Model, Scalar>;
using Vec9 = Vec9T<double>;
using Mat9 = Mat9T<double>;

}  // namespace scalcal
