// The text table of an evaluation (evaluation_report.hpp).
#include "experiments/cli/evaluation_report.hpp"

#include <cmath>
#include <cstdio>

namespace scalcal::cli {

void print_evaluation(std::ostream& out, const std::string& name, const ModelEvaluation& ev) {
  char buf[160];
  out << "program " << name << ": N = " << ev.positions << ", rank " << ev.rank;
  if (!is_default_model(ev.model)) out << " (model " << ev.model_name << ", " << ev.parameters << " parameters)";
  out << ", condition of H^T H = ";
  std::snprintf(buf, sizeof buf, "%.6g\n", ev.condition);
  out << buf;
  out << "  criterion         normalised              raw\n";
  auto row = [&](const std::string& label, double normalised, const std::string& raw_label, double raw) {
    std::snprintf(buf, sizeof buf, "  %-16s %-22.10g %s = %.10g\n", label.c_str(), normalised, raw_label.c_str(), raw);
    out << buf;
  };
  for (auto c : kCriteria)
    row(std::string(criterion_name(c)) + "  " + criterion_label(c, ev.parameters), ev.value(c),
        std::string(criterion_raw_name(c)), ev.raw(c));
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

void print_evaluation(std::ostream& out, const std::string& name, const Evaluation& ev) {
  print_evaluation(out, name, erase_model(ev));
}

}  // namespace scalcal::cli
