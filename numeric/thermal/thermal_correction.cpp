// A thermal calibration at a temperature, and its offset polynomial about any reference (thermal_correction.hpp).
#include "numeric/thermal/thermal_correction.hpp"

#include <algorithm>
#include <cmath>

#include "numeric/calibration/model_calibration.hpp"

namespace scalcal {

double ThermalCorrection::clamped(double celsius) const { return std::clamp(celsius, range.low, range.high); }

FullCorrection ThermalCorrection::at(double celsius) const {
  return correction_of(model.meter_at(coefficients, range.tau(clamped(celsius)), magnitude));
}

Eigen::Matrix<double, 3, Eigen::Dynamic> ThermalCorrection::offset_polynomial(double reference) const {
  // o(T) = |I| sum_j b_j ((T - m) / h)^j with T - m = x + d, x = T - reference, d = reference - m:
  // the coefficient of x^i is |I| sum_{j >= i} b_j h^-j C(j, i) d^(j - i).
  const int k = model.degree;
  const double h = range.half_range(), d = reference - range.middle();
  const std::vector<int> drift = model.drifting();
  const std::vector<int> bias = meter_group(meter_slots(model.base), ParameterGroup::bias);  // by axis, or none
  Eigen::Matrix<double, 3, Eigen::Dynamic> out = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, k + 1);
  if (bias.empty()) return out;
  for (int axis = 0; axis < 3; ++axis) {
    // b_j of this axis's bias: b_0 is the base's bias parameter; b_j the j-th block's entry for it, if it drifts.
    const int r = bias[static_cast<std::size_t>(axis)];
    const auto slot = std::find(drift.begin(), drift.end(), r) - drift.begin();
    std::vector<double> b(static_cast<std::size_t>(k + 1), 0.0);
    b[0] = coefficients(r);
    for (int j = 1; j <= k && slot < static_cast<std::ptrdiff_t>(drift.size()); ++j)
      b[static_cast<std::size_t>(j)] =
          coefficients(model.base_parameters() + (j - 1) * static_cast<Eigen::Index>(drift.size()) + slot);
    for (int i = 0; i <= k; ++i) {
      double sum = 0, binomial = 1;  // C(j, i) for j = i, i + 1, ...
      for (int j = i; j <= k; ++j) {
        if (j > i) binomial = binomial * j / (j - i);
        sum += b[static_cast<std::size_t>(j)] * std::pow(h, -j) * binomial * std::pow(d, j - i);
      }
      out(axis, i) = magnitude * sum;
    }
  }
  return out;
}

}  // namespace scalcal
