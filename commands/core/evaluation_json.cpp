// The JSON form of an evaluation (evaluation_json.hpp).
#include "commands/core/evaluation_json.hpp"

namespace scalcal::commands {

void add_criteria(Json& j, const ModelEvaluation& ev) {
  for (auto c : kCriteria) j[std::string(criterion_name(c))] = ev.value(c);
  for (std::size_t g = 0; g < kGroupNames.size(); ++g)
    if (ev.has_group(static_cast<ParameterGroup>(g))) j["theta_" + std::string(kGroupNames[g])] = ev.theta[g];
}

// The paper's model keeps its documented keys; another model adds `model` and `parameters` first.
Json evaluation_json(const ModelEvaluation& ev) {
  Json names = Json::array();
  for (int r : ev.unidentifiable) names.push_back(std::string(ev.parameter_names[static_cast<std::size_t>(r)]));
  Json j = Json::object();
  if (!is_default_model(ev.model)) {
    j["model"] = std::string(ev.model_name);
    Json p = Json::array();
    for (auto n : ev.parameter_names) p.push_back(std::string(n));
    j["parameters"] = p;
  }
  j["positions"] = ev.positions;
  j["rank"] = ev.rank;
  j["condition"] = ev.condition;
  add_criteria(j, ev);
  for (auto c : kCriteria) j[std::string(criterion_raw_key(c))] = ev.raw(c);
  j["unidentifiable"] = names;
  return j;
}

Json evaluation_json(const ModelEvaluation& ev, const Program& program) {
  Json j = evaluation_json(ev);
  j["program"] = program_json(program);
  Json K = Json::array();
  for (Eigen::Index r = 0; r < ev.K.rows(); ++r) {
    Json row = Json::array();
    for (Eigen::Index c = 0; c < ev.K.cols(); ++c) row.push_back(ev.K(r, c));
    K.push_back(row);
  }
  j["K"] = K;
  return j;
}

Json evaluation_json(const Evaluation& ev) { return evaluation_json(erase_model(ev)); }
Json evaluation_json(const Evaluation& ev, const Program& program) { return evaluation_json(erase_model(ev), program); }

}  // namespace scalcal::commands
