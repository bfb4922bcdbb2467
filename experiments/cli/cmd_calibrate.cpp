// `scalcal calibrate --measurements FILE --magnitude M|auto [...]`: the scalar calibration of one
// meter from bench data (samples grouped by position) or from a raw log (time and raw outputs, or
// --rate, the static intervals found in it), in any units, with the model the layout carries
// (commands/calibration/calibrate.hpp): the result's warnings to stderr, --out, and the text or the JSON to
// stdout. Exit 1 when the fit did not converge.
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "commands/calibration/calibrate.hpp"
#include "commands/calibration/calibrate_gyro.hpp"
#include "commands/calibration/calibrate_json.hpp"
#include "commands/core/common_options.hpp"
#include "experiments/cli/calibrate_gyro_text.hpp"
#include "experiments/cli/calibrate_text.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

// --instrument gyro: a rate table, known turns or hand rotations (commands/calibration/calibrate_gyro.hpp).
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

// A thermal log's fit: each coefficient with its error per degC^j about the reference, the poses' residuals
// against temperature, and what is wrong when the fit may not be used.
std::string thermal_text(const commands::ThermalCalibration& c) {
  const ThermalFit& f = c.fit;
  std::ostringstream out;
  out << c.file << ": " << c.poses.size() << " poses, " << f.model.name() << " about "
      << commands::shortest_text(f.range.middle()) << " degC (polynomials in T - "
      << commands::shortest_text(f.range.middle()) << ", the log's " << c.temperature_column << " over "
      << f.range.text() << " degC)\n";
  if (!f.problem.empty()) out << "NOT USABLE: " << f.problem << "\n";
  out << "converged " << (f.converged ? "yes" : "no") << " in " << f.iterations << " iterations, RMS residual "
      << std::setprecision(3) << f.rms << " |I|, condition " << f.condition << "\n";
  const auto j = commands::to_json(c);
  for (const auto& [name, p] : j["parameters"].items()) {
    char line[200];
    const int power = p["per_degc_power"].get<int>();
    std::snprintf(line, sizeof line, "  %-16s %13.6e +- %.2e%s\n", name.c_str(), p["value_per_degc"].get<double>(),
                  p["standard_error_per_degc"].is_null() ? NAN : p["standard_error_per_degc"].get<double>(),
                  power == 0   ? ""
                  : power == 1 ? " /degC"
                               : (" /degC^" + std::to_string(power)).c_str());
    out << line;
  }
  out << "residual against temperature (|corrected| / |I| - 1 per pose):\n";
  for (std::size_t i = 0; i < c.poses.size() && i < f.residuals.size(); ++i) {
    char line[80];
    std::snprintf(line, sizeof line, "  %8.2f degC  %+.3e\n", c.poses[i].celsius, f.residuals[i]);
    out << line;
  }
  return out.str();
}

int run(const commands::Values& v) {
  if (v.text("--instrument") == "gyro") return run_gyro(v);
  const commands::CalibrateResult r =
      commands::calibrate(commands::calibrate_request(v), terminal_progress("calibrate"));
  print_warnings("calibrate", r.warnings);
  if (r.thermal && !r.thermal->fit.problem.empty())
    std::cerr << "scalcal calibrate: " << r.file << ": " << r.thermal->fit.problem << "\n";
  // One document for --out and --json (header and units included, as a gyroscope's and Python's), so that both
  // state the same `created`. A thermal fit that did not converge is printed, not written.
  const commands::Json file = commands::calibration_file_json(r);
  if (v.given("--out") && (!r.thermal || r.converged()))
    write_output_file(v.text("--out"), [&](std::ostream& f) { write_json(f, file); });
  if (v.flag("--json"))
    print_json(file);
  else
    std::cout << (r.thermal ? thermal_text(*r.thermal) : calibrate_text(r));
  return r.status();
}

const Registration reg(commands::calibrate_table(), run);

}  // namespace
}  // namespace scalcal::cli
