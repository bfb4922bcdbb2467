// `correct`: read a calibration, refuse one that cannot be trusted, apply it (correct.hpp).
#include "commands/correct.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include <Eigen/SVD>
#include <nlohmann/json.hpp>

#include "commands/common_options.hpp"
#include "numeric/calibration/raw_log.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::commands {
namespace {

double number_at(const nlohmann::json& j, const std::string& file, const std::string& key) {
  if (!j.is_number()) throw InputError(file, 0, "'" + key + "' must hold numbers");
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw InputError(file, 0, "'" + key + "' holds a value that is not finite");
  return v;
}

// A reason to distrust the calibration, or "" when there is none.
std::string distrust(const nlohmann::json& j, const FullCorrection& c) {
  // A file without "converged" (written by hand, or by another tool) is taken at its word.
  if (!j.contains("converged")) {
  } else if (!j["converged"].is_boolean()) {
    return "'converged' must be true or false";
  } else if (!j["converged"].get<bool>()) {
    return "its fit did not converge" +
           (j.contains("message") && j["message"].is_string() ? " (" + j["message"].get<std::string>() + ")" : "");
  }
  const Eigen::JacobiSVD<Mat3> svd(c.matrix);
  const double condition = svd.singularValues()(0) / svd.singularValues()(2);
  if (!(condition <= kCorrectionCondition)) {
    std::ostringstream s;
    s << std::setprecision(3) << "its matrix is ill-conditioned (condition " << condition << " > "
      << kCorrectionCondition << ": the axes' gains differ that much, or two axes are nearly parallel)";
    return s.str();
  }
  return "";
}

}  // namespace

FullCorrection read_calibration(const std::string& file, bool force, Warnings& warnings) {
  return calibration_of(parse_json_file_text(read_text_file(file), file, "a JSON object written by `calibrate --out`"),
                        file, force, warnings);
}

FullCorrection calibration_of(const Json& document, const std::string& file, bool force, Warnings& warnings) {
  const nlohmann::json j = nlohmann::json::parse(document.dump(-1, ' ', false, Json::error_handler_t::replace));
  if (j.is_object() && j.contains("model") && j.contains("offset") && (!j.contains("matrix") || j["matrix"].is_null()))
    throw InputError(file, 0,
                     "the " + j["model"].dump() +
                         " calibration has no linear correction (its cubic term "
                         "makes the correction nonlinear); `correct` applies linear ones only");
  if (!j.is_object() || !j.contains("offset") || !j.contains("matrix"))
    throw InputError(file, 0,
                     "needs the keys 'offset' and 'matrix' (write it with `scalcal calibrate ... --out FILE`)");
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
  if (const std::string why = distrust(j, c); !why.empty()) {
    if (!force) throw InputError(file, 0, "refused: " + why + "; --force applies it all the same");
    warnings.push_back({file, "applied with --force although " + why});
  }
  return c;
}

namespace {

CsvTable read_data(const CorrectRequest& q) {
  if (q.table) return *q.table;
  const std::string text = read_text_file(q.file);
  TableFormat f;
  f.nonfinite_allowed = true;
  if (q.format == "text" || (q.format == "auto" && looks_like_text_log(text))) {
    f.whitespace = true;
    f.columns = {"t", "ix", "iy", "iz"};
  }
  return parse_table(text, q.file, f);
}

}  // namespace

const CommandTable& correct_table() {
  Option calibration =
      text_option("--calibration", "CAL.json", "a calibration written by `scalcal calibrate ... --out CAL.json`",
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
  q.format = v.text("--format");
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
  j["x"] = x, j["y"] = y, j["z"] = z, j["modulus"] = modulus;
  return j;
}

CorrectResult correct(const CorrectRequest& q) {
  CorrectResult out;
  out.correction = q.calibration_document
                       ? calibration_of(*q.calibration_document, q.calibration, q.force, out.warnings)
                       : read_calibration(q.calibration, q.force, out.warnings);
  const CsvTable table = read_data(q);
  for (const char* col : {"ix", "iy", "iz"})
    if (!table.has(col)) throw InputError(q.file, 1, std::string("missing column '") + col + "' (need ix,iy,iz)");
  const int ct = time_column(table), cp = table.column("position");
  const int ix = table.column("ix"), iy = table.column("iy"), iz = table.column("iz");
  out.has_t = ct >= 0;
  out.has_position = cp >= 0;
  for (std::size_t k = 0; k < table.rows.size(); ++k) {
    const auto& v = table.rows[k].values;
    CorrectedRow r;
    if (ct >= 0) r.t = v[static_cast<std::size_t>(ct)];
    if (cp >= 0) r.position = v[static_cast<std::size_t>(cp)];
    if (cp >= 0 && std::isnan(r.position) && !table.labels.empty()) r.position_label = table.labels[k];
    r.corrected = out.correction.apply(
        Vec3(v[static_cast<std::size_t>(ix)], v[static_cast<std::size_t>(iy)], v[static_cast<std::size_t>(iz)]));
    // Scaled, so finite for outputs near 1e300; not Eigen's stableNorm, whose summation order follows the
    // vector's address alignment (its last bit changed with the optimisation level).
    r.modulus = std::hypot(r.corrected(0), r.corrected(1), r.corrected(2));
    out.rows.push_back(r);
  }
  return out;
}

}  // namespace scalcal::commands
