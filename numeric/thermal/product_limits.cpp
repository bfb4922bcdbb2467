// Theorem 25's composition of the sphere's and the interval's limits (product_limits.hpp).
#include "numeric/thermal/product_limits.hpp"

#include <cmath>

namespace scalcal {

bool bias_rows_decoupled(const ThermalModel& model) {
  const Eigen::Vector3d eta = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();  // no symmetry of the sphere's
  const Eigen::VectorXd plus = model.row(eta, 0), minus = model.row(-eta, 0);
  std::vector<bool> drifts(static_cast<std::size_t>(model.base_parameters()), false);
  for (int r : model.drifting()) drifts[static_cast<std::size_t>(r)] = true;
  for (int r = 0; r < model.base_parameters(); ++r) {
    const double expected = drifts[static_cast<std::size_t>(r)] ? -plus(r) : plus(r);
    if (std::abs(minus(r) - expected) > 1e-12) return false;
  }
  // The drifting rows must be the position's coordinates (the bias rows x, y, z), whose second moments
  // are I/3 under every measure symmetric under the cube's rotations.
  const auto d = model.drifting();
  if (d.size() != 3) return false;
  for (std::size_t i = 0; i < 3; ++i)
    if (std::abs(plus(d[i]) - eta(static_cast<Eigen::Index>(i))) > 1e-12) return false;
  return true;
}

std::optional<ThermalLimit> thermal_limit(CriterionKind c, const ThermalModel& m, double sphere_limit) {
  const auto interval = optimal_interval_design(c, m.degree);
  if (!interval || !std::isfinite(sphere_limit)) return std::nullopt;
  const int k = m.degree, P = m.base_parameters();
  const bool full = static_cast<int>(m.drifting().size()) == P;
  ThermalLimit l;
  l.criterion = c;
  l.sphere = sphere_limit;
  l.temperature = *interval;
  const double s = sphere_limit;
  auto compose = [&](double one) {
    if (c == CriterionKind::D)
      return full ? std::pow(s, k + 1) * std::pow(one, P) : s * std::pow(27.0, k) * std::pow(one, 3);
    if (c == CriterionKind::A) return full ? s * one : 9 * one + s - 9;
    return s * one;
  };
  if (full) {
    l.form = c == CriterionKind::D ? "D_s^" + std::to_string(k + 1) + " * D_1^" + std::to_string(P)
                                   : std::string(criterion_name(c)) + "_s * " + std::string(criterion_name(c)) + "_1";
  } else {
    if (!bias_rows_decoupled(m) || (c != CriterionKind::D && c != CriterionKind::A)) return std::nullopt;
    l.form = c == CriterionKind::D ? "D_s * 27^" + std::to_string(k) + " * D_1^3" : "9 A_1 + A_s - 9";
  }
  l.value = compose(interval->value);
  l.lower_bound = compose(interval->lower_bound);
  return l;
}

}  // namespace scalcal
