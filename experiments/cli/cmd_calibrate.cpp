// `scalcal calibrate --measurements FILE --magnitude M|auto [...]`: the scalar calibration of one
// meter from bench data (samples grouped by position) or from a raw log (time and raw outputs, or
// --rate, the static intervals found in it), in any units, with the model the layout carries
// (commands/calibrate.hpp): the result's warnings to stderr, --out, and the text or the JSON to
// stdout. Exit 1 when the fit did not converge.
#include <iostream>

#include "commands/calibrate.hpp"
#include "commands/calibrate_gyro.hpp"
#include "commands/calibrate_json.hpp"
#include "experiments/cli/calibrate_gyro_text.hpp"
#include "experiments/cli/calibrate_text.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

// --instrument gyro: a rate table, known turns or hand rotations (commands/calibrate_gyro.hpp).
int run_gyro(const commands::Values& v) {
  const commands::GyroCalibrateResult r = commands::calibrate_gyro(commands::gyro_calibrate_request(v));
  print_warnings("calibrate", r.warnings);
  const commands::Json file = commands::gyro_calibration_file_json(r);
  if (v.given("--out")) write_output_file(v.text("--out"), [&](std::ostream& f) { write_json(f, file); });
  if (v.flag("--json"))
    print_json(file);
  else
    std::cout << calibrate_gyro_text(r);
  return r.status();
}

int run(const commands::Values& v) {
  if (v.text("--instrument") == "gyro") return run_gyro(v);
  const commands::CalibrateResult r =
      commands::calibrate(commands::calibrate_request(v), terminal_progress("calibrate"));
  print_warnings("calibrate", r.warnings);
  if (v.given("--out"))
    write_output_file(v.text("--out"), [&](std::ostream& f) { write_json(f, commands::calibration_file_json(r)); });
  if (v.flag("--json"))
    print_json(commands::to_json(r));
  else
    std::cout << calibrate_text(r);
  return r.status();
}

const Registration reg(commands::calibrate_table(), run);

}  // namespace
}  // namespace scalcal::cli
