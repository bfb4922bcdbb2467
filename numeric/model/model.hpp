// A calibration model as a traits type: the design row h(eta) of the linearised scalar model, its
// Jacobian and curvature, and the names and groups of its P parameters. Evaluation, synthesis and
// the polish take the model as a template parameter, so their fixed-size Eigen types follow from P.
#pragma once
#include <array>
#include <concepts>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "numeric/model/dense_instances.hpp"

namespace scalcal {

template <class Scalar>
using Vec3T = Eigen::Matrix<Scalar, 3, 1>;
template <class Scalar>
using Mat3T = Eigen::Matrix<Scalar, 3, 3>;
using Vec3 = Vec3T<double>;
using Mat3 = Mat3T<double>;

// The measurement positions of a program: unit vectors in the meter's frame.
template <class Scalar>
using PositionsT = std::vector<Vec3T<Scalar>>;

// The groups the paper reports RMS errors for (eq. 7); a model may have any of them.
enum class ParameterGroup { bias = 0, scale = 1, nonorth = 2, cubic = 3 };
inline constexpr std::array<std::string_view, 4> kGroupNames = {"bias", "scale", "nonorth", "cubic"};

// A parameter a meter knows, in the estimator's units (bias / |I|, dk, gamma, c |I|): its name, its group and its
// axis (a non-orthogonality's first axis: xy 0, yz 1, zx 2).
struct MeterParameter {
  std::string_view name;
  ParameterGroup group;
  int axis;
};

// What a model's meter must give (numeric/model/linear_meter.hpp is one): its parameters, the vector it measures
// of an input and the input it compensates a measurement back to, its parameters' values and the meter they
// stand for, whether a group keeps the correction physical = matrix (raw - offset), and its linear part (eq. 2)
// as `linear`, and the reference meter of a size that `simulate --model` draws. A model states its meter as
// `using meter = ...`.
template <class T>
concept CalibrationMeter = requires(const T& m, const Vec3T<double>& v, double magnitude) {
  { T::kParameters[0] } -> std::convertible_to<MeterParameter>;
  { m.measure(v) } -> std::same_as<Vec3T<double>>;
  { m.compensate(v) } -> std::same_as<Vec3T<double>>;
  { m.parameters(magnitude) } -> std::same_as<Eigen::Matrix<double, int(T::kParameters.size()), 1>>;
  { T::from_parameters(m.parameters(magnitude), magnitude) } -> std::same_as<T>;
  { T::linear_group(ParameterGroup::bias) } -> std::same_as<bool>;
  { m.linear.gain() } -> std::same_as<Mat3T<double>>;
  { T::reference(m.linear, magnitude) } -> std::same_as<T>;  // the meter `simulate --model` draws, of a size
};

template <class Model, class Scalar>
using RowT = Eigen::Matrix<Scalar, Model::kParameters, 1>;
template <class Model, class Scalar>
using JacobianT = Eigen::Matrix<Scalar, Model::kParameters, 3>;
template <class Model, class Scalar>
using InformationT = Eigen::Matrix<Scalar, Model::kParameters, Model::kParameters>;

// What a model must give; a missing piece is a compile error wherever the model is used.
//   row(eta)        h(eta), P entries
//   jacobian(eta)   dh/d eta, P x 3
//   curvature(w, eta)  sum_a w_a d^2 h_a / d eta^2 at eta, 3 x 3 (the second derivatives the Newton
//                      step needs; constant for the quadratic models, not for cubic12)
//   meter           the meter whose parameters the model's are (a CalibrationMeter; each name among its own)
template <class M>
concept CalibrationModel = CalibrationMeter<typename M::meter> &&
    requires(const Vec3T<double>& eta, const RowT<M, double>& w) {
  { M::kParameters } -> std::convertible_to<int>;
  { M::name } -> std::convertible_to<std::string_view>;
  { M::parameter_names[0] } -> std::convertible_to<std::string_view>;
  { M::parameter_groups[0] } -> std::convertible_to<ParameterGroup>;
  { M::row(eta) } -> std::same_as<RowT<M, double>>;
  { M::jacobian(eta) } -> std::same_as<JacobianT<M, double>>;
  { M::curvature(w, eta) } -> std::same_as<Mat3T<double>>;
};

// N^P, the normalisation of det K that makes it comparable across N.
template <class Model, class Scalar>
Scalar normalisation(const Scalar& n) {
  Scalar out(1);
  for (int i = 0; i < Model::kParameters; ++i) out *= n;
  return out;
}

// Indices of a group's parameters in the model (empty when the model lacks the group).
template <class Model>
std::vector<int> group_members(ParameterGroup g) {
  std::vector<int> out;
  for (int r = 0; r < Model::kParameters; ++r)
    if (Model::parameter_groups[static_cast<std::size_t>(r)] == g) out.push_back(r);
  return out;
}

}  // namespace scalcal
