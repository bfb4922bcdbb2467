#include "experiments/cli/evaluation_report.hpp"

#include <cmath>
#include <cstdio>


namespace scalcal::cli {

Json evaluation_json(const Evaluation& ev) {
  Json names = Json::array();
  for (int r : ev.unidentifiable) names.push_back(std::string(kParameterNames[r]));
  return Json{{"positions", ev.positions},       {"rank", ev.rank},
              {"condition", ev.condition},       {"D", ev.D},
              {"A", ev.A},                       {"E", ev.E},
              {"S", ev.S},                       {"theta_bias", ev.theta_bias},
              {"theta_scale", ev.theta_scale},   {"theta_nonorth", ev.theta_nonorth},
              {"det_K", ev.det_K},               {"trace_K", ev.trace_K},
              {"lambda_max_K", ev.lambda_max_K}, {"max_diag_K", ev.max_diag_K},
              {"unidentifiable", names}};
}

Json evaluation_json(const Evaluation& ev, const Program& program) {
  Json j = evaluation_json(ev);
  j["program"] = program_json(program);
  j["K"] = matrix_json(ev.K);
  return j;
}

void print_evaluation(std::ostream& out, const std::string& name, const Evaluation& ev) {
  char buf[160];
  out << "program " << name << ": N = " << ev.positions << ", rank " << ev.rank
      << ", condition of H^T H = ";
  std::snprintf(buf, sizeof buf, "%.6g\n", ev.condition);
  out << buf;
  out << "  criterion         normalised              raw\n";
  auto row = [&](const char* label, double normalised, const char* raw_label, double raw) {
    std::snprintf(buf, sizeof buf, "  %-16s %-22.10g %s = %.10g\n", label, normalised, raw_label, raw);
    out << buf;
  };
  row("D  N^9 det K", ev.D, "det K", ev.det_K);
  row("A  N trace K", ev.A, "trace K", ev.trace_K);
  row("E  N lambda_max", ev.E, "lambda_max K", ev.lambda_max_K);
  row("S  N max K(r,r)", ev.S, "max K(r,r)", ev.max_diag_K);
  std::snprintf(buf, sizeof buf, "  RMS errors sqrt(N max K(r,r)): theta_bias %.6g  theta_scale %.6g  theta_nonorth %.6g\n",
                ev.theta_bias, ev.theta_scale, ev.theta_nonorth);
  out << buf;
}

}  // namespace scalcal::cli
