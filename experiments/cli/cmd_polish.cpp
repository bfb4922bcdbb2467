// `scalcal polish PROGRAM --criterion C [--digits P] [--out FILE] [--json]`: the program polished by
// Newton's method in MPFR on its first-order conditions, with the certificate's second-order verdict
// (commands/research/polish.hpp); --out writes the polished program. Exit 1 when the polish did not converge.
#include <iomanip>
#include <iostream>

#include "commands/research/polish.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

int run(const commands::Values& v) {
  const auto r = commands::polish(commands::polish_request(v), terminal_progress("polish"));
  print_warnings("polish", r.warnings);
  const PolishResult& p = r.polished;
  if (v.given("--out")) write_program_file(v.text("--out"), p.program);
  if (v.flag("--json")) {
    print_json(commands::to_json(r));
  } else {
    const SecondOrder& s = r.second_order;
    std::cout << criterion_name(r.criterion) << " = " << p.value_digits << "  (" << p.digits << " digits, residual "
              << std::setprecision(3) << p.residual << ", " << p.summary.iterations
              << " Newton steps, N = " << r.positions << (p.converged() ? "" : ", not converged") << ")\n"
              << "second order: " << s.text << (s.reason.empty() ? "" : " (" + s.reason + ")") << "\n";
  }
  // Not converged: the digits printed are fewer than asked, and a script must notice.
  return p.converged() ? 0 : 1;
}

const Registration reg(commands::polish_table(), run);

}  // namespace
}  // namespace scalcal::cli
