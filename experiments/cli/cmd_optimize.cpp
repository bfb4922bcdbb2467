// `scalcal optimize --positions N|--from PROGRAM --criterion C [--model NAME] [--region SPEC]...
// [--starts K] [--seed S] [--threads T] [--digits P] [--local auto|newton|lbfgs|ipopt] [--out FILE]
// [--json]`: the optimal program by a multistart, optionally polished to P digits (commands/design/optimize.hpp);
// with --digits, --out and the JSON program are the polished program.
#include <iomanip>
#include <iostream>
#include <string>

#include "commands/design/optimize.hpp"
#include "commands/design/thermal_optimize.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

// "proven: proofs/cap_es_limits.md", "certified", "numerical".
std::string limit_status(const commands::ReportedLimit& l) {
  std::string s(status_name(l.statement.status));
  if (!l.statement.theorem.empty()) s += ": " + std::string(l.statement.theorem);
  return s;
}

// A thermal program: the product's split, its value against the thermal limit, the oven's plan.
void print_thermal(const commands::ThermalOptimizeResult& t) {
  const auto& e = t.evaluation;
  const auto i = static_cast<std::size_t>(t.criterion.index());
  std::cout << criterion_name(t.criterion) << " = " << std::setprecision(10) << e.values[i].value_or(0)
            << "  (N = " << t.positions << " = " << t.sphere_positions << " positions x "
            << t.positions / t.sphere_positions << " at " << t.design.points.size() << " set-points, model "
            << e.model.name() << ")\n";
  for (const auto& row : e.limits.rows)
    if (row.criterion == t.criterion) {
      if (row.limit)
        std::cout << "limit " << std::setprecision(10) << row.limit->value << " (" << row.status
                  << ": proofs/thermal_product.md), efficiency " << std::setprecision(9) << e.efficiency[i].value_or(0)
                  << " (D as its " << e.model.parameters() << "th root)\n";
      else
        std::cout << "no limit (" << row.note << ")\n";
    }
  std::cout << "sphere program: " << criterion_name(t.criterion) << " = " << std::setprecision(10)
            << t.sphere.synthesis.value << " at N = " << t.sphere_positions << "\n";
  std::cout << "oven plan (set-points in increasing order):\n";
  int row = 1;
  for (std::size_t k = 0; k < t.design.points.size(); ++k) {
    const int rows = t.counts[k] * t.sphere_positions;
    std::cout << "  " << std::fixed << std::setprecision(2) << e.range.celsius(t.design.points[k]) << " degC: rows "
              << row << "-" << row + rows - 1 << " (" << t.counts[k] << " x the " << t.sphere_positions
              << " positions; weight " << std::setprecision(4) << t.design.weights[k] << ")\n"
              << std::defaultfloat;
    row += rows;
  }
}

void print_text(const commands::OptimizeResult& r) {
  if (r.thermal) return print_thermal(*r.thermal);
  const SynthesisResult& s = r.synthesis;
  std::cout << criterion_name(r.criterion) << " = " << std::setprecision(15) << r.value << "  (N = " << r.positions
            << ", " << s.hits << " of " << s.starts << " starts reached it (stopped: " << s.stopping << "), "
            << s.distinct << (s.distinct == 1 ? " program" : " distinct programs") << " up to symmetry, "
            << std::setprecision(3) << s.seconds << " s)\n";
  if (r.designed_on) std::cout << "designed on " << r.designed_on->text() << "\n";
  if (r.limit && !is_default_model(r.model))
    std::cout << "model " << model_name(r.model) << ": limit " << std::setprecision(10) << *r.limit << " ("
              << limit_status(*r.limit_statement) << "), efficiency " << std::setprecision(9) << *r.efficiency
              << " (limit / value; D as its " << model_parameters(r.model) << "th root)\n";
  else if (r.limit && r.region)
    std::cout << "on " << r.region->text() << ": limit " << std::setprecision(10) << *r.limit << " ("
              << limit_status(*r.limit_statement) << "), efficiency " << std::setprecision(9) << *r.efficiency
              << " (limit / value; D as its 9th root)\n";
  if (r.polished)
    std::cout << criterion_name(r.criterion) << " = " << r.polished->value_digits << "  (" << r.polished->digits
              << " digits, residual " << std::setprecision(3) << r.polished->residual << ", "
              << r.polished->summary.iterations << " Newton steps)\n";
}

int run(const commands::Values& v) {
  const auto r = commands::optimize(commands::optimize_request(v), terminal_progress("optimize"));
  print_warnings("optimize", r.warnings);
  if (v.given("--out") && r.thermal)
    write_output_file(v.text("--out"),
                      [&](std::ostream& out) { write_thermal_program_csv(out, r.thermal->evaluation.program); });
  else if (v.given("--out"))
    write_program_file(v.text("--out"), r.program, r.columns,
                       {r.region && !r.region->is_sphere() ? r.region->specs : std::vector<std::string>{}, {}});
  if (v.flag("--json"))
    print_json(commands::to_json(r));
  else
    print_text(r);
  return 0;
}

const Registration reg(commands::optimize_table(), run);

}  // namespace
}  // namespace scalcal::cli
