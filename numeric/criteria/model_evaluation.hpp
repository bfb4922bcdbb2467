// An Evaluation whose model is chosen at run time (--model): the same numbers with dynamic sizes,
// the model's parameter names and groups, and only the thetas of the groups the model has. The CLI
// and every front end report this type; the templated core stays fixed-size.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal {

struct ModelEvaluation {
  ModelKind model = ModelKind::paper9;
  std::string_view model_name = "paper9";
  int parameters = 9;
  std::vector<std::string_view> parameter_names;
  std::vector<ParameterGroup> parameter_groups;
  int positions = 0, rank = 0;
  double condition = 0;
  // Every registered criterion by CriterionKind index, normalised and raw (evaluation.hpp).
  std::array<double, kCriterionCount> values{}, raw_values{};
  // theta of each group in kGroupNames order; NaN for a group the model does not have.
  std::array<double, 4> theta{};
  Eigen::MatrixXd information, K;
  Eigen::VectorXd K_eigenvalues;
  std::vector<int> unidentifiable;

  bool full_rank() const { return rank == parameters; }
  double value(CriterionKind c) const { return values[static_cast<std::size_t>(c.index())]; }
  double raw(CriterionKind c) const { return raw_values[static_cast<std::size_t>(c.index())]; }
  double value(std::string_view name) const { return value(*parse_criterion(name)); }
  bool has_group(ParameterGroup g) const;
};

template <class Model>
ModelEvaluation erase_model(const EvaluationTpl<double, Model>& ev, ModelKind kind) {
  ModelEvaluation out;
  out.model = kind;
  out.model_name = Model::name;
  out.parameters = Model::kParameters;
  out.parameter_names.assign(Model::parameter_names.begin(), Model::parameter_names.end());
  out.parameter_groups.assign(Model::parameter_groups.begin(), Model::parameter_groups.end());
  out.positions = ev.positions;
  out.rank = ev.rank;
  out.condition = ev.condition;
  out.values = ev.values;
  out.raw_values = ev.raw_values;
  out.theta = {ev.theta_bias, ev.theta_scale, ev.theta_nonorth, ev.theta_cubic};
  out.information = ev.information;
  out.K = ev.K;
  out.K_eigenvalues = ev.K_eigenvalues;
  out.unidentifiable = ev.unidentifiable;
  return out;
}

ModelEvaluation erase_model(const Evaluation& ev);  // the paper's model

// evaluate<Model>(program) for the model behind `model`.
ModelEvaluation evaluate(ModelKind model, const Program& program);

}  // namespace scalcal
