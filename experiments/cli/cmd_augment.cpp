// `scalcal augment --program FILE --add K [--criterion C] [--model NAME] [--region SPEC]... [--out FILE]
// [--json]`: the lab's positions and the K added inside the bench's region (commands/augment.hpp).
#include <cmath>
#include <cstdio>
#include <iostream>

#include "commands/augment.hpp"
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
  if (v.given("--out")) write_program_file(v.text("--out"), a.program, r.columns);
  if (v.flag("--json")) {
    print_json(commands::to_json(r));
    return 0;
  }
  if (r.model != ModelKind::paper9) std::cout << "model " << model_name(r.model) << ", ";
  std::cout << criterion_name(r.criterion) << ": " << value_text(a.value_before) << " with the " << r.given
            << " given positions, " << value_text(a.value) << " with " << a.added.size() << " added on "
            << r.region.text() << ":\n";
  for (const Vec3& x : a.added) {
    char line[96];
    std::snprintf(line, sizeof line, "  %.9f, %.9f, %.9f\n", x.x(), x.y(), x.z());
    std::cout << line;
  }
  return 0;
}

const Registration reg(commands::augment_table(), run);

}  // namespace
}  // namespace scalcal::cli
