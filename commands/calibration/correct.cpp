// `correct`: read a calibration, refuse one that cannot be trusted, apply it (correct.hpp).
#include "commands/calibration/correct.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "commands/calibration/thermal_calibrate.hpp"
#include "commands/core/common_options.hpp"
#include "numeric/calibration/raw_log.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {

FullCorrection linear_correction(const CalibrationFile& c) {
  if (c.nonlinear)
    throw InputError(c.name, 0,
                     "the " + c.model +
                         " calibration has no linear correction (its cubic term makes the correction nonlinear); "
                         "`correct` applies linear ones only, and applying its matrix alone would drop the cubic "
                         "term");
  return c.correction;
}

namespace {

CsvTable read_data(const CorrectRequest& q) {
  if (q.table) return *q.table;
  const std::string text = read_text_file(q.file);
  TableFormat f;
  f.nonfinite_allowed = true;
  if (q.format == LogFormat::text || (q.format == LogFormat::automatic && looks_like_text_log(text))) {
    f.whitespace = true;
    f.columns = {"t", "ix", "iy", "iz"};
  }
  return parse_table(text, q.file, f);
}

}  // namespace

const CommandTable& correct_table() {
  Option calibration =
      text_option("--calibration", "CAL.json", words("a calibration written by `scalcal calibrate ... {out CAL.json}`"),
                  "file path", kRequired);
  calibration.takes_document = true;
  Option measurements = text_option(
      "--measurements", "FILE", "raw data: CSV with ix,iy,iz (and a time column or position, kept), or text t ix iy iz",
      "file path", kRequired);
  measurements.takes_columns = true;
  static const CommandTable table{
      "correct",
      "apply a calibration to raw data: corrected x, y, z and modulus (refuses one that did not converge)",
      21,
      {calibration, measurements,
       choice_option("--format", {"auto", "csv", "text"},
                     "the file: auto (text when the first line starts with a number), csv, or text (t ix iy iz)",
                     "auto"),
       flag_option(
           "--force",
           "apply a calibration that would be refused (its fit did not converge, or its matrix is ill-conditioned)"),
       out_option("write the corrected CSV there instead of to standard output")}};
  return table;
}

CorrectRequest correct_request(const Values& v) {
  CorrectRequest q;
  q.calibration = v.text("--calibration");
  q.file = v.text("--measurements");
  q.format = log_format_named(v.text("--format"));
  q.force = v.flag("--force");
  if (const auto it = v.documents.find("--calibration"); it != v.documents.end()) q.calibration_document = it->second;
  if (const auto it = v.tables.find("--measurements"); it != v.tables.end()) q.table = it->second;
  return q;
}

Json to_json(const CorrectResult& r) {
  Json t = Json::array(), position = Json::array(), x = Json::array(), y = Json::array(), z = Json::array(),
       modulus = Json::array();
  for (const auto& row : r.rows) {
    t.push_back(row.t), position.push_back(row.position);
    x.push_back(row.corrected(0)), y.push_back(row.corrected(1)), z.push_back(row.corrected(2));
    modulus.push_back(row.modulus);
  }
  Json j = Json::object();
  if (r.has_t) j["t"] = t;
  if (r.has_position) j["position"] = position;
  if (r.has_temperature) {
    Json celsius = Json::array();
    for (const auto& row : r.rows) celsius.push_back(row.celsius);
    j["t_c"] = celsius;
  }
  j["x"] = x, j["y"] = y, j["z"] = z, j["modulus"] = modulus;
  return j;
}

namespace {

// A thermal calibration's temperature column, and a warning for the rows outside its range.
int thermal_column(const CalibrationFile& c, const CsvTable& table, const std::string& file) {
  if (!c.thermal) return -1;
  const int tc = temperature_column(table);
  if (tc < 0)
    throw InputError(file, 1,
                     "the calibration " + c.name + " is thermal (" + c.model + " over " + c.thermal->range.text() +
                         " degC): the data need their temperature, a column temp, temperature or t_c (degC)");
  return tc;
}

void warn_outside(const CalibrationFile& c, const CorrectRequest& q, int outside, CorrectResult& out) {
  if (outside > 0)
    out.warnings.push_back({q.file, std::to_string(outside) + " row(s) outside the calibration's " +
                                        c.thermal->range.text() +
                                        " degC were corrected at the nearest end of that range (as PX4 and ArduPilot "
                                        "hold their polynomials)"});
}

}  // namespace

CorrectResult correct(const CorrectRequest& q) {
  CorrectResult out;
  const CalibrationFile c = q.calibration_document
                                ? calibration_file_of(*q.calibration_document, q.calibration, q.force, out.warnings)
                                : read_calibration_file(q.calibration, q.force, out.warnings);
  out.correction = c.thermal ? c.correction : linear_correction(c);
  const CsvTable table = read_data(q);
  for (const char* col : {"ix", "iy", "iz"})
    if (!table.has(col)) throw InputError(q.file, 1, std::string("missing column '") + col + "' (need ix,iy,iz)");
  const int ct = time_column(table), cp = table.column("position"), tc = thermal_column(c, table, q.file);
  const int ix = table.column("ix"), iy = table.column("iy"), iz = table.column("iz");
  out.has_t = ct >= 0;
  out.has_position = cp >= 0;
  out.has_temperature = tc >= 0;
  int outside = 0;
  for (std::size_t k = 0; k < table.rows.size(); ++k) {
    const auto& v = table.rows[k].values;
    CorrectedRow r;
    if (ct >= 0) r.t = v[static_cast<std::size_t>(ct)];
    if (cp >= 0) r.position = v[static_cast<std::size_t>(cp)];
    if (cp >= 0 && std::isnan(r.position) && !table.labels.empty()) r.position_label = table.labels[k];
    const Vec3 raw(v[static_cast<std::size_t>(ix)], v[static_cast<std::size_t>(iy)], v[static_cast<std::size_t>(iz)]);
    if (tc >= 0) {
      r.celsius = v[static_cast<std::size_t>(tc)];
      if (!std::isfinite(r.celsius) && raw.allFinite())
        throw InputError(q.file, table.rows[k].line, "the row's temperature is not a number");
      if (std::isfinite(r.celsius) && r.celsius != c.thermal->clamped(r.celsius)) ++outside;
    }
    r.corrected = (tc >= 0 && std::isfinite(r.celsius) ? c.thermal->at(r.celsius) : out.correction).apply(raw);
    // Scaled, so finite for outputs near 1e300; not Eigen's stableNorm, whose summation order follows the
    // vector's address alignment (its last bit changed with the optimisation level).
    r.modulus = std::hypot(r.corrected(0), r.corrected(1), r.corrected(2));
    if (raw.allFinite() && !(r.corrected.allFinite() && std::isfinite(r.modulus)))
      throw InputError(q.file, table.rows[k].line,
                       "the calibration maps this row to a value that is not finite (beyond 1e308: is its matrix "
                       "in these raw units?)");
    out.rows.push_back(r);
  }
  if (tc >= 0) warn_outside(c, q, outside, out);
  return out;
}

}  // namespace scalcal::commands
