// `scalcal certify PROGRAM --criterion C [--digits P] [--json]`: the interval certificate for one program
// (commands/research/certify.hpp): the limit attained (proven: an exact program within `radius`) or missed (a
// certified local optimum whose value lies in `enclosure`, above the limit), or why the claim stays
// numerical.
#include <iomanip>
#include <iostream>

#include "commands/research/certify.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"

namespace scalcal::cli {
namespace {

int run(const commands::Values& v) {
  const auto r = commands::certify(commands::certify_request(v), terminal_progress("certify"));
  print_warnings("certify", r.warnings);
  if (v.flag("--json")) {
    print_json(commands::to_json(r));
    return 0;
  }
  const CertifyResult& c = r.certificate;
  std::cout << "status     " << status_text(c.status) << "\n"
            << "criterion  " << criterion_name(r.criterion) << " = " << std::setprecision(12) << c.value << " (limit "
            << c.limit << "), N = " << r.positions << "\n";
  if (!c.radius.empty()) std::cout << "radius     " << c.radius << "\n";
  if (r.local())
    std::cout << "enclosure  [" << c.enclosure_lo << ", " << c.enclosure_hi << "] (" << c.enclosure_digits
              << " digits)\n";
  std::cout << "method     " << c.method << " (" << c.unknowns << " unknowns)\n"
            << "reason     " << c.reason << "\n"
            << "seconds    " << std::setprecision(3) << c.seconds << "\n";
  return 0;
}

const Registration reg(commands::certify_table(), run);

}  // namespace
}  // namespace scalcal::cli
