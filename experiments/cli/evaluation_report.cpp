#include "experiments/cli/evaluation_report.hpp"

#include <cmath>
#include <cstdio>

namespace scalcal::cli {

// The paper's model keeps its documented keys; another model adds `model` and `parameters` first
// and has theta keys only for the groups it has.
Json evaluation_json(const ModelEvaluation& ev) {
  Json names = Json::array();
  for (int r : ev.unidentifiable) names.push_back(std::string(ev.parameter_names[static_cast<std::size_t>(r)]));
  Json j = Json::object();
  if (ev.model != ModelKind::paper9) {
    j["model"] = std::string(ev.model_name);
    Json p = Json::array();
    for (auto n : ev.parameter_names) p.push_back(std::string(n));
    j["parameters"] = p;
  }
  j["positions"] = ev.positions;
  j["rank"] = ev.rank;
  j["condition"] = ev.condition;
  j["D"] = ev.D;
  j["A"] = ev.A;
  j["E"] = ev.E;
  j["S"] = ev.S;
  for (std::size_t g = 0; g < kGroupNames.size(); ++g)
    if (ev.has_group(static_cast<ParameterGroup>(g))) j["theta_" + std::string(kGroupNames[g])] = ev.theta[g];
  j["det_K"] = ev.det_K;
  j["trace_K"] = ev.trace_K;
  j["lambda_max_K"] = ev.lambda_max_K;
  j["max_diag_K"] = ev.max_diag_K;
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

void print_evaluation(std::ostream& out, const std::string& name, const ModelEvaluation& ev) {
  char buf[160];
  out << "program " << name << ": N = " << ev.positions << ", rank " << ev.rank;
  if (ev.model != ModelKind::paper9) out << " (model " << ev.model_name << ", " << ev.parameters << " parameters)";
  out << ", condition of H^T H = ";
  std::snprintf(buf, sizeof buf, "%.6g\n", ev.condition);
  out << buf;
  out << "  criterion         normalised              raw\n";
  auto row = [&](const std::string& label, double normalised, const char* raw_label, double raw) {
    std::snprintf(buf, sizeof buf, "  %-16s %-22.10g %s = %.10g\n", label.c_str(), normalised, raw_label, raw);
    out << buf;
  };
  row("D  N^" + std::to_string(ev.parameters) + " det K", ev.D, "det K", ev.det_K);
  row("A  N trace K", ev.A, "trace K", ev.trace_K);
  row("E  N lambda_max", ev.E, "lambda_max K", ev.lambda_max_K);
  row("S  N max K(r,r)", ev.S, "max K(r,r)", ev.max_diag_K);
  out << "  RMS errors sqrt(N max K(r,r)):";
  const char* gap = " ";
  for (std::size_t g = 0; g < kGroupNames.size(); ++g)
    if (ev.has_group(static_cast<ParameterGroup>(g))) {
      std::snprintf(buf, sizeof buf, "%stheta_%s %.6g", gap, std::string(kGroupNames[g]).c_str(), ev.theta[g]);
      out << buf;
      gap = "  ";
    }
  out << "\n";
}

Json evaluation_json(const Evaluation& ev) { return evaluation_json(erase_model(ev)); }
Json evaluation_json(const Evaluation& ev, const Program& program) { return evaluation_json(erase_model(ev), program); }
void print_evaluation(std::ostream& out, const std::string& name, const Evaluation& ev) {
  print_evaluation(out, name, erase_model(ev));
}

}  // namespace scalcal::cli
