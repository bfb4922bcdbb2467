// `scalcal correct --calibration CAL.json --measurements FILE [--format auto|csv|text] [--force] [--out FILE]`:
// applies a calibration written by `calibrate --out CAL.json` (its offset and matrix, physical =
// matrix (raw - offset)) to every row of raw data, and writes the corrected x, y, z and their
// modulus as CSV. A calibration whose fit did not converge or whose matrix is ill-conditioned is
// refused (exit 2, with the reason) unless --force (commands/correct.hpp). The matrix carries the
// paper's convention for the rotation scalar calibration cannot see (phi_kj = phi_jk:
// numeric/calibration/full_correction.hpp).
#include <charconv>
#include <iostream>
#include <memory>

#include "commands/correct.hpp"
#include "experiments/cli/calibrate_text.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

std::string shortest(double v) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  return std::string(buffer, end);
}

int run(const commands::CorrectRequest& q, const std::string& out) {
  const commands::CorrectResult r = commands::correct(q);
  print_warnings("correct", r.warnings);
  const auto write = [&](std::ostream& f) {
    f << (r.has_t ? "t," : "") << (r.has_position ? "position," : "") << "x,y,z,modulus\n";
    for (const auto& row : r.rows) {
      if (r.has_t) f << shortest(row.t) << ',';
      if (r.has_position) f << shortest(row.position) << ',';
      f << shortest(row.corrected(0)) << ',' << shortest(row.corrected(1)) << ',' << shortest(row.corrected(2)) << ','
        << shortest(row.modulus) << '\n';
    }
  };
  if (out.empty()) {
    write(std::cout);
  } else {
    write_output_file(out, write);
  }
  return 0;
}

Runner setup(CLI::App& app) {
  auto q = std::make_shared<commands::CorrectRequest>();
  auto out = std::make_shared<std::string>();
  add_text(app, "--calibration", q->calibration, "CAL.json",
           {"a calibration written by `scalcal calibrate ... --out CAL.json`", "file path", kRequired});
  add_text(app, "--measurements", q->file, "FILE",
           {"raw data: CSV with ix,iy,iz (and a time column or position, kept), or text t ix iy iz", "file path",
            kRequired});
  add_choice(app, "--format", q->format, {"auto", "csv", "text"},
             {"the file: auto (text when the first line starts with a number), csv, or text (t ix iy iz)"});
  add_switch(app, "--force", q->force,
             "apply a calibration that would be refused (its fit did not converge, or its matrix is ill-conditioned)");
  add_text(app, "--out", *out, "FILE", {"write the corrected CSV there instead of to standard output", "file path"});
  return [q, out] { return run(*q, *out); };
}

const Registration reg({"correct",
                        "correct --calibration CAL.json --measurements FILE [--format auto|csv|text] [--force] "
                        "[--out FILE]",
                        "apply a calibration to raw data: corrected x, y, z and modulus (refuses one that did not "
                        "converge)",
                        45, setup});

}  // namespace
}  // namespace scalcal::cli
