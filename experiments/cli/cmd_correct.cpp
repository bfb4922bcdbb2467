// `scalcal correct --calibration CAL.json --measurements FILE [--format auto|csv|text] [--out FILE]`:
// applies a calibration written by `calibrate --out CAL.json` (its offset and matrix, physical =
// matrix (raw - offset)) to every row of raw data, and writes the corrected x, y, z and their
// modulus as CSV. The matrix carries the paper's convention for the rotation scalar calibration
// cannot see (phi_kj = phi_jk: numeric/calibration/full_correction.hpp).
#include <charconv>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "experiments/cli/command.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/output_file.hpp"
#include "numeric/calibration/full_correction.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/raw_log.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  std::string calibration, file, format = "auto", out;
};

double number_at(const nlohmann::json& j, const std::string& file, const std::string& key) {
  if (!j.is_number()) throw InputError(file, 0, "'" + key + "' must hold numbers");
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw InputError(file, 0, "'" + key + "' holds a value that is not finite");
  return v;
}

FullCorrection read_calibration(const std::string& file) {
  const std::string text = read_text_file(file);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(file, 0, std::string("not a JSON object written by `calibrate --out`: ") + e.what());
  }
  if (j.is_object() && j.contains("model") && j.contains("offset") && !j.contains("matrix"))
    throw InputError(file, 0, "the " + j["model"].dump() + " calibration has no linear correction (its cubic term "
                              "makes the correction nonlinear); `correct` applies linear ones only");
  if (!j.is_object() || !j.contains("offset") || !j.contains("matrix"))
    throw InputError(file, 0, "needs the keys 'offset' and 'matrix' (write it with `scalcal calibrate ... --out FILE`)");
  const auto& o = j["offset"];
  const auto& m = j["matrix"];
  if (!o.is_array() || o.size() != 3) throw InputError(file, 0, "'offset' must be three numbers");
  if (!m.is_array() || m.size() != 3) throw InputError(file, 0, "'matrix' must be three rows of three numbers");
  FullCorrection c;
  for (int i = 0; i < 3; ++i) {
    c.offset(i) = number_at(o[static_cast<std::size_t>(i)], file, "offset");
    const auto& row = m[static_cast<std::size_t>(i)];
    if (!row.is_array() || row.size() != 3) throw InputError(file, 0, "'matrix' must be three rows of three numbers");
    for (int k = 0; k < 3; ++k) c.matrix(i, k) = number_at(row[static_cast<std::size_t>(k)], file, "matrix");
  }
  if (!(std::abs(c.matrix.determinant()) > 0)) throw InputError(file, 0, "'matrix' is singular");
  return c;
}

std::string shortest(double v) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
  return std::string(buffer, end);
}

int run(const Options& o) {
  const FullCorrection c = read_calibration(o.calibration);
  const std::string text = read_text_file(o.file);
  CsvTable table;
  if (o.format == "text" || (o.format == "auto" && looks_like_text_log(text))) {
    TableFormat f;
    f.whitespace = true;
    f.columns = {"t", "ix", "iy", "iz"};
    f.nonfinite_allowed = true;
    table = parse_table(text, o.file, f);
  } else {
    TableFormat f;
    f.nonfinite_allowed = true;
    table = parse_table(text, o.file, f);
  }
  for (const char* col : {"ix", "iy", "iz"})
    if (!table.has(col)) throw InputError(o.file, 1, std::string("missing column '") + col + "' (need ix,iy,iz)");
  const int ct = table.column("t"), cp = table.column("position");
  const int ix = table.column("ix"), iy = table.column("iy"), iz = table.column("iz");
  const auto write = [&](std::ostream& out) {
    out << (ct >= 0 ? "t," : "") << (cp >= 0 ? "position," : "") << "x,y,z,modulus\n";
    for (const auto& row : table.rows) {
      const auto& v = row.values;
      const Vec3 p = c.apply(Vec3(v[static_cast<std::size_t>(ix)], v[static_cast<std::size_t>(iy)], v[static_cast<std::size_t>(iz)]));
      if (ct >= 0) out << shortest(v[static_cast<std::size_t>(ct)]) << ',';
      if (cp >= 0) out << shortest(v[static_cast<std::size_t>(cp)]) << ',';
      out << shortest(p(0)) << ',' << shortest(p(1)) << ',' << shortest(p(2)) << ',' << shortest(p.norm()) << '\n';
    }
  };
  if (o.out.empty()) {
    write(std::cout);
  } else {
    write_output_file(o.out, write);
  }
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_text(app, "--calibration", o->calibration, "CAL.json",
           {"a calibration written by `scalcal calibrate ... --out CAL.json`", "file path", kRequired});
  add_text(app, "--measurements", o->file, "FILE",
           {"raw data: CSV with ix,iy,iz (and t or position, kept), or text t ix iy iz", "file path", kRequired});
  add_choice(app, "--format", o->format, {"auto", "csv", "text"},
             {"the file: auto (text when the first line starts with a number), csv, or text (t ix iy iz)"});
  add_text(app, "--out", o->out, "FILE", {"write the corrected CSV there instead of to standard output", "file path"});
  return [o] { return run(*o); };
}

const Registration reg({"correct", "correct --calibration CAL.json --measurements FILE [--format auto|csv|text] [--out FILE]",
                        "apply a calibration to raw data: corrected x, y, z and modulus", 45, setup});

}  // namespace
}  // namespace scalcal::cli
