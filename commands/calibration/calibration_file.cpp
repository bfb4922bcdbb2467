// The one reader of calibration files (calibration_file.hpp).
#include "commands/calibration/calibration_file.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <Eigen/SVD>

#include "commands/core/common_options.hpp"
#include "numeric/calibration/model_calibration.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal::commands {
namespace {

std::string short_number(double v) {
  std::ostringstream s;
  s << std::setprecision(3) << v;
  return s.str();
}

double number_at(const Json& j, const std::string& file, const std::string& key) {
  if (!j.is_number()) throw InputError(file, 0, "'" + key + "' must hold numbers, not " + j.dump());
  const double v = j.get<double>();
  if (!std::isfinite(v)) throw InputError(file, 0, "'" + key + "' holds a value that is not finite");
  return v;
}

// An optional number: absent or null gives NaN.
double optional_number(const Json& d, const std::string& file, const char* key) {
  if (!d.contains(key) || d[key].is_null()) return NAN;
  return number_at(d[key], file, key);
}

int format_version_of(const Json& d, const std::string& file) {
  if (!d.contains("format_version")) return 0;
  const Json& v = d["format_version"];
  if (!v.is_number_integer() && !v.is_number_unsigned())
    throw InputError(file, 0, "'format_version' must be an integer, not " + json_text(v));
  const long long n = v.get<long long>();
  if (n < 1 || n > kCalibrationFormatVersion)
    throw InputError(file, 0,
                     "format_version " + std::to_string(n) + " is not one this scalcal reads (1 to " +
                         std::to_string(kCalibrationFormatVersion) +
                         "): a newer scalcal wrote it, or it is not a "
                         "calibration file");
  return static_cast<int>(n);
}

// A thermal calibration (calibrate --model BASE+Tk --out): its range, |I| and every coefficient's value.
void read_thermal(const Json& d, const std::string& file, const ThermalModel& model, CalibrationFile& c) {
  ThermalCorrection t;
  t.model = model;
  if (!d.contains("temperature_c") || !d["temperature_c"].is_string())
    throw InputError(file, 0, "a thermal calibration needs 'temperature_c', the range it was fitted over (\"T1..T2\")");
  try {
    t.range = parse_temperature_range(d["temperature_c"].get<std::string>());
  } catch (const std::invalid_argument& e) {
    throw InputError(file, 0, std::string("'temperature_c': ") + e.what());
  }
  if (!d.contains("magnitude")) throw InputError(file, 0, "a thermal calibration needs 'magnitude', |I| in its units");
  t.magnitude = number_at(d["magnitude"], file, "magnitude");
  if (!(t.magnitude > 0)) throw InputError(file, 0, "'magnitude' must be positive");
  if (!d.contains("parameters") || !d["parameters"].is_object())
    throw InputError(file, 0, "a thermal calibration needs 'parameters', each coefficient as {\"value\": ...}");
  const Json& p = d["parameters"];
  const std::vector<std::string> names = model.parameter_names();
  for (const auto& [key, value] : p.items())
    if (std::find(names.begin(), names.end(), key) == names.end())
      throw InputError(file, 0, "parameter '" + key + "' is not one of model " + c.model + "'s");
  t.coefficients.resize(static_cast<Eigen::Index>(names.size()));
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (!p.contains(names[i]) || !p[names[i]].is_object() || !p[names[i]].contains("value"))
      throw InputError(file, 0, "model " + c.model + "'s parameter '" + names[i] + "' is missing (or has no value)");
    t.coefficients(static_cast<Eigen::Index>(i)) =
        number_at(p[names[i]]["value"], file, "parameters." + names[i] + ".value");
  }
  c.thermal = t;
}

// The model's name and whether its correction is nonlinear; its parameters checked against it.
void check_model(const Json& d, const std::string& file, CalibrationFile& c) {
  if (!d.contains("model")) return;
  if (!d["model"].is_string()) throw InputError(file, 0, "'model' must be a model's name");
  c.model = d["model"].get<std::string>();
  std::optional<ThermalModel> thermal;
  try {
    thermal = parse_thermal_model(c.model);
  } catch (const std::invalid_argument& e) {
    throw InputError(file, 0, "model '" + c.model + "': " + e.what());
  }
  if (thermal) return read_thermal(d, file, *thermal, c);
  const auto kind = parse_model(c.model);
  if (!kind)
    throw InputError(file, 0, "model '" + c.model + "' is not a registered model (" + scalcal::model_names(", ") + ")");
  c.nonlinear = !corrects_linearly(meter_slots(*kind));
  if (!d.contains("parameters")) return;
  const Json& p = d["parameters"];
  if (!p.is_object()) throw InputError(file, 0, "'parameters' must be an object of the model's parameters");
  const auto names = visit_model(*kind, [](auto m) {
    std::vector<std::string> n;
    for (const auto& s : decltype(m)::parameter_names) n.emplace_back(s);
    return n;
  });
  for (const auto& [key, value] : p.items()) {
    if (std::find(names.begin(), names.end(), key) == names.end())
      throw InputError(file, 0, "parameter '" + key + "' is not one of model " + c.model + "'s");
    if (!value.is_null()) number_at(value, file, "parameters." + key);
  }
  for (const auto& n : names)
    if (!p.contains(n)) throw InputError(file, 0, "model " + c.model + "'s parameter '" + n + "' is missing");
}

// One unit entry: null (not given), counts (raw only), "unit modulus" (physical with auto), a unit.
std::optional<Unit> unit_entry(const Json& u, const char* key, const std::string& file, int version, bool& counts) {
  if (!u.contains(key) || u[key].is_null()) return std::nullopt;
  if (!u[key].is_string()) throw InputError(file, 0, std::string("'units.") + key + "' must be a unit's name or null");
  const std::string s = u[key].get<std::string>();
  if (is_count_unit(s)) {
    counts = true;
    return std::nullopt;
  }
  if (s == "unit modulus") return std::nullopt;
  const auto unit = parse_unit(s);
  if (!unit && version >= 2)
    throw InputError(
        file, 0, std::string("'units.") + key + "' = '" + s + "' is not a unit scalcal knows (" + unit_names() + ")");
  return unit;  // version 1 wrote free labels: one that is not a unit is not a unit
}

void read_units(const Json& d, const std::string& file, CalibrationFile& c) {
  const bool magnitude_auto = d.contains("magnitude") && d["magnitude"] == "auto";
  c.units.unit_modulus = magnitude_auto;
  c.units.field_strength = optional_number(d, file, "field_strength");
  if (!d.contains("units") || d["units"].is_null()) return;
  const Json& u = d["units"];
  if (!u.is_object()) throw InputError(file, 0, "'units' must be an object {\"raw\": ..., \"physical\": ...}");
  bool counts = false;
  c.units.raw = unit_entry(u, "raw", file, c.format_version, counts);
  c.units.raw_counts = counts;
  bool unused = false;
  const auto physical = unit_entry(u, "physical", file, c.format_version, unused);
  if (magnitude_auto && physical && c.format_version >= 2)
    throw InputError(file, 0,
                     "it says physical units " + std::string(physical->name) +
                         " but its magnitude is auto, which maps the field to modulus 1 (\"unit modulus\")");
  if (!magnitude_auto) c.units.physical = physical;
  if (c.instrument)
    for (const auto& unit : {c.units.raw, c.units.physical})
      if (unit && unit->quantity != quantity_of(*c.instrument))
        throw InputError(file, 0,
                         "its unit " + std::string(unit->name) + " is not a unit of " +
                             std::string(quantity_name(quantity_of(*c.instrument))) + ", which a " +
                             std::string(instrument_noun(*c.instrument)) + " measures");
}

void read_instrument(const Json& d, const std::string& file, CalibrationFile& c) {
  if (!d.contains("instrument") || d["instrument"].is_null()) return;
  if (!d["instrument"].is_string()) throw InputError(file, 0, "'instrument' must be accel, mag or gyro");
  c.instrument = parse_instrument(d["instrument"].get<std::string>());
  if (!c.instrument)
    throw InputError(file, 0, "'instrument' = " + json_text(d["instrument"]) + " is not accel, mag or gyro");
}

// The worst condition of a thermal correction's matrix over its range (the ends and 99 points between), and
// its correction at the middle.
double thermal_condition(CalibrationFile& c) {
  const ThermalCorrection& t = *c.thermal;
  double worst = 0;
  for (int i = 0; i <= 100; ++i) {
    const Eigen::JacobiSVD<Mat3> svd(t.at(t.range.low + (t.range.high - t.range.low) * i / 100).matrix);
    const double condition = svd.singularValues()(0) / svd.singularValues()(2);
    worst = std::isnan(condition) || std::isnan(worst) ? NAN : std::max(worst, condition);
  }
  c.correction = t.at(t.range.middle());
  if (!(worst <= kSingularCondition))
    throw InputError(
        c.name, 0,
        "its matrix is singular somewhere in " + t.range.text() + " degC (condition " + short_number(worst) + ")");
  return worst;
}

// 'linear' repeats what the model implies (cubic12's correction is not a matrix); a file that says otherwise
// was edited by hand or not written by calibrate, and which of the two to believe is not ours to guess.
void check_linear(const Json& d, const std::string& file, const CalibrationFile& c) {
  if (!d.contains("linear")) return;
  if (!d["linear"].is_boolean()) throw InputError(file, 0, "'linear' must be true or false");
  if (d["linear"].get<bool>() != c.nonlinear) return;
  if (c.model.empty())
    throw InputError(file, 0,
                     "'linear' is false but the file names no model, and only a model's cubic terms make a "
                     "correction nonlinear");
  throw InputError(file, 0,
                   std::string("'linear' is ") + (c.nonlinear ? "true" : "false") + " but model " + c.model +
                       (c.nonlinear ? " corrects nonlinearly" : " corrects by a matrix"));
}

// The offset and matrix, and the matrix's condition.
double read_correction(const Json& d, const std::string& file, CalibrationFile& c) {
  if (c.thermal) return thermal_condition(c);
  check_linear(d, file, c);
  if (!d.contains("offset") || (!d.contains("matrix") && !c.nonlinear))
    throw InputError(file, 0,
                     words("needs the keys 'offset' and 'matrix' (write it with `scalcal calibrate ... {out FILE}`)"));
  const Json& o = d["offset"];
  if (!o.is_array() || o.size() != 3) throw InputError(file, 0, "'offset' must be three numbers");
  for (int i = 0; i < 3; ++i) c.correction.offset(i) = number_at(o[static_cast<std::size_t>(i)], file, "offset");
  if (c.nonlinear && (!d.contains("matrix") || d["matrix"].is_null())) return 1;
  const Json& m = d["matrix"];
  if (!m.is_array() || m.size() != 3) throw InputError(file, 0, "'matrix' must be three rows of three numbers");
  for (int i = 0; i < 3; ++i) {
    const Json& row = m[static_cast<std::size_t>(i)];
    if (!row.is_array() || row.size() != 3) throw InputError(file, 0, "'matrix' must be three rows of three numbers");
    for (int k = 0; k < 3; ++k) c.correction.matrix(i, k) = number_at(row[static_cast<std::size_t>(k)], file, "matrix");
  }
  const Eigen::JacobiSVD<Mat3> svd(c.correction.matrix);
  const double condition = svd.singularValues()(0) / svd.singularValues()(2);
  if (!(condition <= kSingularCondition))
    throw InputError(file, 0,
                     "'matrix' is singular (condition " + short_number(condition) +
                         "): it maps some raw change to no change at all");
  return condition;
}

// A reason to distrust the calibration, or "" when there is none.
std::string distrust(const Json& d, double condition) {
  if (d.contains("converged")) {
    if (!d["converged"].is_boolean()) return "'converged' must be true or false";
    if (!d["converged"].get<bool>())
      return "its fit did not converge" +
             (d.contains("message") && d["message"].is_string() ? " (" + d["message"].get<std::string>() + ")" : "");
  }
  if (d.contains("problem") && d["problem"].is_string()) return d["problem"].get<std::string>();
  if (condition > kCorrectionCondition)
    return "its matrix is ill-conditioned (condition " + short_number(condition) + " > " +
           short_number(kCorrectionCondition) + ": the axes' gains differ that much, or two axes are nearly parallel)";
  return "";
}

}  // namespace

CalibrationFile read_calibration_file(const std::string& path, bool force, Warnings& warnings) {
  return calibration_file_of(
      parse_json_file_text(read_text_file(path), path, words("a JSON object written by `calibrate {out}`")), path,
      force, warnings);
}

CalibrationFile calibration_file_of(const Json& document, const std::string& file, bool force, Warnings& warnings) {
  if (!document.is_object())
    throw InputError(file, 0, "not a calibration: a JSON object with 'offset' and 'matrix' was expected");
  CalibrationFile c;
  c.name = file;
  c.document = document;
  c.format_version = format_version_of(document, file);
  check_model(document, file, c);
  read_instrument(document, file, c);
  read_units(document, file, c);
  c.sample_rate = optional_number(document, file, "sample_rate");
  c.noise = optional_number(document, file, "noise");
  const double condition = read_correction(document, file, c);
  if (const std::string why = distrust(document, condition); !why.empty()) {
    if (!force) throw InputError(file, 0, "refused: " + why + words("; {force} applies it all the same"));
    warnings.push_back({file, words("used with {force} although ") + why});
  }
  return c;
}

Json units_json(const CalibrationUnits& u, bool raw_counts) {
  const Json raw = u.raw ? Json(std::string(u.raw->name)) : raw_counts ? Json("counts") : Json();
  const Json physical = u.unit_modulus ? Json("unit modulus")
                        : u.physical   ? Json(std::string(u.physical->name))
                                       : Json();
  return Json{{"raw", raw}, {"physical", physical}};
}

}  // namespace scalcal::commands
