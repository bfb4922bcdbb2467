// `scalcal optimize --positions N|--from PROGRAM --criterion C [--model NAME] [--region SPEC]...
// [--starts K] [--seed S] [--threads T] [--digits P] [--local auto|newton|lbfgs|ipopt] [--out FILE]
// [--json]`: the optimal program by a multistart, optionally polished to P digits (commands/optimize.hpp);
// with --digits, --out and the JSON program are the polished program.
#include <iomanip>
#include <iostream>
#include <string>

#include "commands/optimize.hpp"
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

void print_text(const commands::OptimizeResult& r) {
  const SynthesisResult& s = r.synthesis;
  std::cout << criterion_name(r.criterion) << " = " << std::setprecision(15) << s.value << "  (N = " << r.positions
            << ", " << s.hits << " of " << s.starts << " starts reached it (stopped: " << s.stopping << "), "
            << s.distinct << (s.distinct == 1 ? " program" : " distinct programs") << " up to symmetry, "
            << std::setprecision(3) << s.seconds << " s)\n";
  if (r.designed_on) std::cout << "designed on " << r.designed_on->text() << "\n";
  if (r.limit && r.model != ModelKind::paper9)
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
  if (v.given("--out"))
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
