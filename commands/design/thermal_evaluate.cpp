// A thermal program's criteria and efficiency (thermal_evaluate.hpp).
#include "commands/design/thermal_evaluate.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "commands/core/common_options.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/thermal/information_criteria.hpp"

namespace scalcal::commands {
namespace {

std::vector<double> distinct(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }), v.end());
  return v;
}

std::string list(const std::vector<double>& v) {
  std::string out;
  for (double x : v) out += (out.empty() ? "" : ", ") + shortest_text(x);
  return out;
}

}  // namespace

ThermalEvaluation evaluate_thermal(const std::string& name, const ThermalProgram& p, const ThermalModel& model,
                                   const TemperatureRange& range, const std::optional<Region>& region,
                                   const Progress& progress) {
  ThermalEvaluation e;
  e.name = name;
  e.model = model;
  e.range = range;
  e.program = p;
  e.setpoints = distinct(p.celsius);
  const int k = model.degree;
  if (static_cast<int>(e.setpoints.size()) < k + 1)
    throw InputError(name, 0,
                     std::to_string(e.setpoints.size()) + " distinct temperature(s) (" + list(e.setpoints) +
                         " degC) cannot identify a polynomial of degree " + std::to_string(k) +
                         " in temperature: " + model.name() + " needs " + std::to_string(k + 1) +
                         words(" set-points at least (`scalcal limits {model} ") + model.name() +
                         words(" {temperature} ") + range.text() + "` prints the optimal ones)");
  const Eigen::MatrixXd m = thermal_information(model, range, p);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m);
  const Eigen::VectorXd& l = eig.eigenvalues();
  e.condition = l(l.size() - 1) / l(0);
  if (!(l(0) > 1e-12 * l(l.size() - 1)))
    throw InputError(name, 0,
                     "the positions cannot identify " + model.name() + " (information matrix singular: condition " +
                         shortest_text(e.condition) + "); each set-point's positions must identify " +
                         std::string(model_name(model.base)) + " across the set-points, at least " +
                         std::to_string(model.base_parameters()) + " positions in general position");
  if (e.setpoints.front() < range.low - 1e-9 || e.setpoints.back() > range.high + 1e-9)
    e.warnings.push_back({name, words("temperatures outside {temperature} ") + range.text() + " (" + list(e.setpoints) +
                                    " degC): the limits are for that range, so an efficiency above 1 is possible"});
  e.limits = thermal_limits(model, range, region, progress);
  for (const auto& row : e.limits.rows) {
    const auto i = static_cast<std::size_t>(row.criterion.index());
    e.values[i] = information_criterion(row.criterion, m);
    if (row.limit && e.values[i])
      e.efficiency[i] = efficiency(row.criterion, row.limit->value, *e.values[i], model.parameters());
  }
  return e;
}

Json to_json(const ThermalEvaluation& e) {
  Json j{{"program", e.name},        {"model", e.model.name()},         {"parameters", e.model.parameters()},
         {"rows", e.program.size()}, {"temperature_c", e.range.text()}, {"setpoints_c", e.setpoints},
         {"condition", e.condition}};
  Json values = Json::object(), eff = Json::object();
  for (const auto& row : e.limits.rows) {
    const auto i = static_cast<std::size_t>(row.criterion.index());
    const std::string key(criterion_name(row.criterion));
    values[key] = e.values[i] ? Json(*e.values[i]) : Json(nullptr);
    eff[key] = e.efficiency[i] ? Json(*e.efficiency[i]) : Json(nullptr);
  }
  j["criteria"] = values;
  j["efficiency"] = eff;
  j["limits"] = to_json(e.limits);
  return j;
}

}  // namespace scalcal::commands
