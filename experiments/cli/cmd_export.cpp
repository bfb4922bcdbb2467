// `scalcal export CALIBRATION --format json|magcal|imu_tk|kalibr|px4|ardupilot [--instrument accel|mag]
// [--instance N] [--force] [--out FILE] [--json]`: a calibration in another tool's form
// (commands/bench/export.hpp), to --out or standard output.
#include <iostream>

#include "commands/bench/export.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

int run(const commands::Values& v) {
  const commands::ExportResult r = commands::export_calibration(commands::export_request(v));
  print_warnings("export", r.warnings);
  if (v.given("--out")) write_output_file(v.text("--out"), [&](std::ostream& out) { out << r.output.text; });
  if (v.flag("--json"))
    print_json(commands::to_json(r));
  else if (!v.given("--out"))
    std::cout << r.output.text;
  return 0;
}

const Registration reg(commands::export_table(), run);

}  // namespace
}  // namespace scalcal::cli
