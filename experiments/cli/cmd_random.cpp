// `scalcal random --positions N --count R [--seed S] [--criterion C] [--model NAME] [--region SPEC]...
// [--threads T] [--out FILE] [--json]`: the best of R uniform random programs (commands/design/random.hpp).
#include <iomanip>
#include <iostream>

#include "commands/design/random.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

int run(const commands::Values& v) {
  const auto r = commands::random_programs(commands::random_request(v), terminal_progress("random"));
  print_warnings("random", r.warnings);
  if (v.given("--out"))  // the region line only for a restricted region, as optimize writes it
    write_program_file(v.text("--out"), r.search.program, {},
                       {r.region.empty() ? std::vector<std::string>{} : r.request.regions, {}});
  if (v.flag("--json")) {
    print_json(commands::to_json(r));
    return 0;
  }
  const auto& q = r.request;
  std::cout << "best " << criterion_name(q.criterion) << " = " << std::setprecision(12) << r.search.best << " of "
            << r.search.count << " random programs of " << q.positions << " positions"
            << (is_default_model(q.model) ? "" : " (model " + std::string(model_name(q.model)) + ")")
            << (r.region.empty() ? "" : " on " + r.region) << " (" << std::setprecision(3) << r.search.seconds << " s, "
            << r.search.count / r.search.seconds / 1e6 << " M programs/s)\n";
  return 0;
}

const Registration reg(commands::random_table(), run);

}  // namespace
}  // namespace scalcal::cli
