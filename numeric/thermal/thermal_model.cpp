// Thermal models' names, parameters and rows (thermal_model.hpp).
#include "numeric/thermal/thermal_model.hpp"

#include <stdexcept>

#include "numeric/calibration/model_calibration.hpp"

namespace scalcal {
namespace {

// A thermal calibration is written, applied and exported as a matrix and an offset at each temperature: a model
// may be a thermal base only if each of its parameters lies in a linear group of its meter.
template <class Model>
constexpr bool corrects_as_matrix_and_offset() {
  for (ParameterGroup g : Model::parameter_groups)
    if (!Model::meter::linear_group(g)) return false;
  return true;
}
template <class... Models>
constexpr bool thermal_bases_correct_linearly(TypeList<Models...>) {
  return ((!model_supports<Models>(ModelCapability::thermal_base) || corrects_as_matrix_and_offset<Models>()) && ...);
}
static_assert(thermal_bases_correct_linearly(RegisteredModels{}),
              "a model with thermal_base must correct as a matrix and an offset (its meter's linear groups only)");

}  // namespace

std::string ThermalModel::name() const {
  return std::string(model_name(base)) + (bias_only ? "+bias:T" : "+T") + std::to_string(degree);
}

std::vector<int> ThermalModel::drifting() const {
  return visit_model(base, [this](auto M) {
    using Model = decltype(M);
    std::vector<int> out;
    for (int r = 0; r < Model::kParameters; ++r)
      if (!bias_only || Model::parameter_groups[static_cast<std::size_t>(r)] == ParameterGroup::bias) out.push_back(r);
    return out;
  });
}

int ThermalModel::parameters() const { return base_parameters() + static_cast<int>(drifting().size()) * degree; }

std::vector<std::string> ThermalModel::parameter_names() const {
  std::vector<std::string> out = visit_model(base, [](auto M) {
    using Model = decltype(M);
    return std::vector<std::string>(Model::parameter_names.begin(), Model::parameter_names.end());
  });
  const std::vector<std::string> base_names = out;
  for (int j = 1; j <= degree; ++j)
    for (int r : drifting()) out.push_back(base_names[static_cast<std::size_t>(r)] + "_T" + std::to_string(j));
  return out;
}

Eigen::VectorXd ThermalModel::row(const Eigen::Vector3d& eta, double tau) const {
  const Eigen::VectorXd h = visit_model(base, [&eta](auto M) {
    using Model = decltype(M);
    return Eigen::VectorXd(Model::row(Vec3T<double>(eta)));
  });
  const std::vector<int> d = drifting();
  Eigen::VectorXd out(parameters());
  out.head(h.size()) = h;
  double power = 1;
  Eigen::Index at = h.size();
  for (int j = 1; j <= degree; ++j) {
    power *= tau;
    for (int r : d) out(at++) = h(r) * power;
  }
  return out;
}

Eigen::VectorXd ThermalModel::base_parameters_at(const Eigen::VectorXd& theta, double tau) const {
  Eigen::VectorXd X = theta.head(base_parameters());
  const std::vector<int> d = drifting();
  Eigen::Index at = X.size();
  double power = 1;
  for (int j = 1; j <= degree; ++j) {
    power *= tau;
    for (int r : d) X(r) += theta(at++) * power;
  }
  return X;
}

std::string calibrated_thermal_models() {
  return "BASE+Tk or BASE+bias:Tk with BASE one of " + models_supporting(ModelCapability::thermal_base);
}

Meter ThermalModel::meter_at(const Eigen::VectorXd& theta, double tau, double magnitude) const {
  return model_meter(base, base_parameters_at(theta, tau), magnitude).linear();
}

std::optional<ThermalModel> parse_thermal_model(const std::string& text) {
  const auto plus = text.find('+');
  if (plus == std::string::npos) return std::nullopt;
  const std::string base = text.substr(0, plus);
  std::string drift = text.substr(plus + 1);
  const auto kind = parse_model(base);
  if (!kind) throw std::invalid_argument("'" + text + "': '" + base + "' is not a model (" + model_names(", ") + ")");
  ThermalModel m;
  m.base = *kind;
  if (drift.rfind("bias:", 0) == 0) {
    m.bias_only = true;
    drift = drift.substr(5);
  }
  const bool digits =
      drift.size() >= 2 && drift[0] == 'T' && drift.find_first_not_of("0123456789", 1) == std::string::npos;
  if (!digits || drift.size() > 3)
    throw std::invalid_argument("'" + text + "' is not BASE+Tk or BASE+bias:Tk (k = 1.." +
                                std::to_string(kMaxThermalDegree) + ", for example paper9+T3)");
  m.degree = std::stoi(drift.substr(1));
  if (m.degree < 1 || m.degree > kMaxThermalDegree)
    throw std::invalid_argument("'" + text + "': the degree in temperature must be 1.." +
                                std::to_string(kMaxThermalDegree));
  if (m.bias_only && m.drifting().empty())
    throw std::invalid_argument("'" + text + "': " + base + " has no bias parameters");
  return m;
}

}  // namespace scalcal
