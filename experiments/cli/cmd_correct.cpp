// `scalcal correct --calibration CAL.json --measurements FILE [--format auto|csv|text] [--force] [--out FILE]`:
// applies a calibration written by `calibrate --out CAL.json` (physical = matrix (raw - offset)) to
// every row of raw data and writes the corrected x, y, z and their modulus as CSV (commands/calibration/correct.hpp).
// A calibration whose fit did not converge or whose matrix is ill-conditioned is refused (exit 2, with
// the reason) unless --force.
#include <iostream>

#include "commands/calibration/correct.hpp"
#include "commands/core/common_options.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

using commands::shortest_text;

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"#;") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

int run(const commands::Values& v) {
  const commands::CorrectResult r = commands::correct(commands::correct_request(v));
  print_warnings("correct", r.warnings);
  const auto write = [&](std::ostream& f) {
    f << (r.has_t ? "t," : "") << (r.has_position ? "position," : "") << (r.has_temperature ? "t_c," : "")
      << "x,y,z,modulus\n";
    for (const auto& row : r.rows) {
      if (r.has_t) f << shortest_text(row.t) << ',';
      if (r.has_position)  // a label as the file had it, quoted (RFC 4180) when it holds a comma or quote
        f << (row.position_label.empty() ? shortest_text(row.position) : csv_field(row.position_label)) << ',';
      if (r.has_temperature) f << shortest_text(row.celsius) << ',';
      f << shortest_text(row.corrected(0)) << ',' << shortest_text(row.corrected(1)) << ','
        << shortest_text(row.corrected(2)) << ',' << shortest_text(row.modulus) << '\n';
    }
  };
  if (v.given("--out"))
    write_output_file(v.text("--out"), write);
  else
    write(std::cout);
  return 0;
}

const Registration reg(commands::correct_table(), run);

}  // namespace
}  // namespace scalcal::cli
