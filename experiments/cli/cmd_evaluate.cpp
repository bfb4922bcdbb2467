// `scalcal evaluate PROGRAM [--model NAME] [--region SPEC]... [--out FILE] [--json]`: the criteria of
// one program, as the paper compares them (commands/design/evaluate.hpp); --out writes the program itself
// as CSV (any catalogue name becomes a file), with tilt and azimuth on a one-zone region.
#include <cstdio>
#include <iostream>
#include <sstream>

#include "commands/core/common_options.hpp"
#include "commands/design/evaluate.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/evaluation_report.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

// A thermal program: its rows and set-points, each criterion's value, efficiency and limit's label.
void print_thermal(const commands::ThermalEvaluation& e) {
  std::cout << e.name << ": " << e.program.size() << " rows at " << e.setpoints.size() << " set-points (";
  for (std::size_t i = 0; i < e.setpoints.size(); ++i)
    std::cout << (i ? ", " : "") << commands::shortest_text(e.setpoints[i]);
  std::cout << " degC) under " << e.model.name() << " over " << e.range.text() << " degC\n";
  for (const auto& row : e.limits.rows) {
    const auto i = static_cast<std::size_t>(row.criterion.index());
    char buffer[200];
    std::snprintf(buffer, sizeof buffer, "%s = %.6g", std::string(criterion_name(row.criterion)).c_str(),
                  e.values[i] ? *e.values[i] : 0.0);
    std::cout << buffer;
    if (e.efficiency[i]) {
      std::snprintf(buffer, sizeof buffer, "   efficiency %.4f against the %s limit %.6g", *e.efficiency[i],
                    row.status.c_str(), row.limit->value);
      std::cout << buffer;
    } else {
      std::cout << "   (no limit: " << row.note << ")";
    }
    std::cout << "\n";
  }
  std::cout << "(D's efficiency is the " << e.model.parameters() << "th root of limit / value)\n";
}

void print_text(const commands::EvaluateResult& r) {
  if (r.thermal) return print_thermal(*r.thermal);
  std::ostringstream text;
  print_evaluation(text, r.name, r.evaluation);
  if (r.region) {
    text << "efficiency on " << r.region->text() << " (limit / value; D as its 9th root):";
    for (auto c : kCriteria) {
      const auto& e = r.efficiency[static_cast<std::size_t>(c.index())];
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.4f", e ? *e : 0.0);
      text << " " << criterion_name(c) << " " << (e ? std::string(buffer) : std::string("n/a (no known limit)"));
    }
    text << "\nlimits on " << r.region->text() << ":";
    const char* separator = " ";
    for (auto c : kCriteria) {
      const auto& l = r.limits[static_cast<std::size_t>(c.index())];
      if (!l) continue;
      // A theorem's value to 10 digits; a solver's to 6, which its last bits (they differ with the BLAS
      // kernel) do not reach.
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, l->statement.status == LimitStatus::proven ? "%.10g" : "%.6g",
                    l->statement.value);
      text << separator << criterion_name(c) << " " << buffer << " (" << status_name(l->statement.status);
      if (!l->statement.theorem.empty()) text << ": " << l->statement.theorem;
      text << ")";
      separator = ", ";
    }
    text << "\n";
  }
  std::cout << text.str();
}

int run(const commands::Values& v) {
  const auto r = commands::evaluate(commands::evaluate_request(v), terminal_progress("evaluate"));
  print_warnings("evaluate", r.warnings);
  if (v.given("--out") && r.thermal)
    write_output_file(v.text("--out"), [&](std::ostream& out) { write_thermal_program_csv(out, r.thermal->program); });
  else if (v.given("--out"))
    write_program_file(v.text("--out"), r.program, r.columns,
                       {r.region ? r.region->specs : std::vector<std::string>{}, {}});
  if (v.flag("--json"))
    print_json(commands::to_json(r));
  else
    print_text(r);
  return 0;
}

const Registration reg(commands::evaluate_table(), run);

}  // namespace
}  // namespace scalcal::cli
