// A thermal model: a registered model whose parameters (all of them, or only the biases) are
// polynomials of degree k in the normalised temperature tau (temperature_range.hpp), named like
// "paper9+T3" or "paper9+bias:T3". Its linearised row at (eta, tau) is h(eta) (x) (1, tau, ..., tau^k)
// for the drifting parameters and h(eta) for the others: a Kronecker product, which is why its optimal
// programs factor into the sphere's and the interval's (product_limits.hpp, proofs/thermal_product.md).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "numeric/model/meter.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal {

inline constexpr int kMaxThermalDegree = 6;

struct ThermalModel {
  ModelKind base = ModelKind::paper9;
  int degree = 1;          // k, 1..kMaxThermalDegree
  bool bias_only = false;  // only the bias group drifts

  std::string name() const;  // "paper9+T3", "paper9+bias:T3"
  int base_parameters() const { return model_parameters(base); }
  std::vector<int> drifting() const;  // the base parameters that drift, in the base model's order
  int parameters() const;             // base + drifting x degree
  // The base's names, then each drifting parameter's coefficient of tau^j as NAME_Tj, j = 1..k.
  std::vector<std::string> parameter_names() const;
  // The linearised row at a position and a normalised temperature, in parameter_names() order.
  Eigen::VectorXd row(const Eigen::Vector3d& eta, double tau) const;
  // The base model's parameters at a normalised temperature from coefficients theta (parameter_names()
  // order): X(tau) = X_0 + sum_j X_j tau^j for the drifting ones.
  Eigen::VectorXd base_parameters_at(const Eigen::VectorXd& theta, double tau) const;
  // The base model's meter at tau, as eq. (2) (the base's parameters placed among its meter's, the others zero):
  // what the fit compensates with, the rehearsal measures with and the correction applies. Bases with the
  // thermal_base capability only, whose meters correct as a matrix and an offset.
  Meter meter_at(const Eigen::VectorXd& theta, double tau, double magnitude) const;
};

// A thermal name when `text` is one ("BASE+Tk" or "BASE+bias:Tk" with a registered base); nullopt when
// it has no '+'; throws std::invalid_argument with the reason for a malformed one.
std::optional<ThermalModel> parse_thermal_model(const std::string& text);

// "BASE+Tk or BASE+bias:Tk with BASE one of paper9, axis6, bias3": the thermal models a log is fitted and rehearsed
// under (the bases with the thermal_base capability), for refusals.
std::string calibrated_thermal_models();

}  // namespace scalcal
