// `scalcal augment --program FILE --add K [--criterion C] [--model NAME] [--region SPEC]... [--out FILE]
// [--json]`: the lab's positions and the K added inside the bench's region (commands/design/augment.hpp).
#include <cmath>
#include <cstdio>
#include <iostream>

#include "commands/design/augment.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

std::string value_text(double v) {
  if (!std::isfinite(v)) return "rank-deficient";
  char s[32];
  std::snprintf(s, sizeof s, "%.10g", v);
  return s;
}

int run(const commands::Values& v) {
  const auto r = commands::augment(commands::augment_request(v), terminal_progress("augment"));
  print_warnings("augment", r.warnings);
  const AugmentedProgram& a = r.augmented;
  if (v.given("--out"))
    write_program_file(v.text("--out"), a.program, r.columns,
                       {r.region.is_sphere() ? std::vector<std::string>{} : r.region.specs, {}});
  if (v.flag("--json")) {
    print_json(commands::to_json(r));
    return 0;
  }
  if (!is_default_model(r.model)) std::cout << "model " << model_name(r.model) << ", ";
  std::cout << criterion_name(r.criterion) << ": " << value_text(a.value_before) << " with the " << r.given
            << " given positions, " << value_text(a.value) << " with " << a.added.size() << " added on "
            << r.region.text() << ":\n";
  for (const Vec3& x : a.added) {
    char line[96];
    std::snprintf(line, sizeof line, "  %.9f, %.9f, %.9f\n", x.x(), x.y(), x.z());
    std::cout << line;
  }
  std::cout << "joint optimisation of the added positions: " << a.starts << (a.starts == 1 ? " start" : " starts")
            << ", the best from start " << a.best_start
            << " (start 0, from the greedy exchange: " << value_text(a.value_greedy) << ")\n";
  if (r.efficiency) {
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, "efficiency %.6f against the limit %.10g", *r.efficiency, *r.limit);
    std::cout << numbers << " on " << r.region.text() << " (limit / value"
              << (r.criterion == CriterionKind::D
                      ? ", D as its " + std::to_string(model_parameters(r.model)) + "th root"
                      : "")
              << ")\n";
  }
  return 0;
}

const Registration reg(commands::augment_table(), run);

}  // namespace
}  // namespace scalcal::cli
