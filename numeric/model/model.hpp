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
template <class M>
concept CalibrationModel = requires(const Vec3T<double>& eta, const RowT<M, double>& w) {
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
