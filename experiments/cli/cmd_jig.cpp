// `scalcal jig NAME [--criterion C] [--starts K] [--seed S] [--instrument accel|gyro] [--out FILE] [--json]`: the best
// way to mount the meter in a printable jig (commands/bench/jig.hpp), as a sheet: the value, what is proven, the
// meter's axes in jig coordinates, the criteria before and after.
#include <cstdio>
#include <iostream>

#include "commands/bench/jig.hpp"
#include "commands/core/evaluation_json.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

void print_limit(const commands::JigResult& r) {
  if (!r.limit) {
    std::printf("limit: none known for criterion %s\n", std::string(criterion_name(r.criterion)).c_str());
    return;
  }
  char number[32];
  std::snprintf(number, sizeof number, "%.10g", *r.limit);
  const bool same = r.limit_exact == number;
  std::printf("limit %s%s%s, ratio %.10g: %s, %s (%s)\n", r.limit_exact.c_str(), same ? "" : " = ", same ? "" : number,
              r.value / *r.limit, r.claim_status.c_str(), r.claim_proven ? "proven" : "numerical",
              r.claim_reason.c_str());
}

void print_text(const commands::JigResult& r) {
  const std::string c(criterion_name(r.criterion));
  std::printf("%s (%d faces), criterion %s\n", r.jig.c_str(), r.faces, c.c_str());
  if (!r.instrument_note.empty()) std::printf("%s\n", r.instrument_note.c_str());
  const bool exact_here = !r.exact.empty() && r.orientation_exact.empty();
  std::printf("best mounting: %s = %.10g (default mounting %.10g)%s%s\n", c.c_str(), r.value, r.value_default,
              exact_here ? ", exactly " : "", exact_here ? r.exact.c_str() : "");
  std::printf("  %s: %s\n", r.status.c_str(), r.method.c_str());
  if (!r.orientation_exact.empty())
    std::printf("  at the exact mounting %s the value is exactly %s%s\n", r.orientation_exact.c_str(), r.exact.c_str(),
                r.at_limit ? "" : " (its optimality is numerical)");
  print_limit(r);
  std::printf("meter axes in jig coordinates (mount the meter so that its axes point along these):\n");
  const char* axis[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i)
    std::printf("  %s = (%15.12f, %15.12f, %15.12f)\n", axis[i], r.orientation(i, 0), r.orientation(i, 1),
                r.orientation(i, 2));
  std::printf("  criterion        default           best\n");
  Json b = Json::object(), a = Json::object();
  commands::add_criteria(b, erase_model(r.before));
  commands::add_criteria(a, erase_model(r.after));
  for (const auto& [name, value] : b.items())
    std::printf("  %-13s %14.8g %14.8g\n", name.c_str(), value.get<double>(), a[name].get<double>());
}

int run(const commands::Values& v) {
  const auto r = commands::jig(commands::jig_request(v), terminal_progress("jig"));
  print_warnings("jig", r.warnings);
  if (v.given("--out")) write_program_file(v.text("--out"), r.program);
  if (v.flag("--json"))
    print_json(commands::to_json(r));
  else
    print_text(r);
  return 0;
}

const Registration reg(commands::jig_table(), run);

}  // namespace
}  // namespace scalcal::cli
