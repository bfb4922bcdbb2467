// `scalcal export` (export.hpp): the calibration read and checked once, then its registered format.
#include "commands/bench/export.hpp"

#include <cmath>

#include "commands/core/common_options.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {
namespace {

// The calibration file's keys the json target keeps (what it is of, in which units, by what).
constexpr const char* kKept[] = {"created",   "tool",  "sensor", "instrument", "units",
                                 "magnitude", "model", "region", "converged",  "field_strength"};

std::vector<std::string> format_choices() {
  std::vector<std::string> names;
  for (const auto& f : export_formats()) names.emplace_back(f.name);
  return names;
}

std::string format_help() {
  std::string s = "the target and its convention:";
  for (const auto& f : export_formats()) s += " " + std::string(f.name) + " (" + std::string(f.what) + ");";
  s.back() = ' ';
  return s + "(docs/bench.md, Export)";
}

Instrument instrument_of(const ExportRequest& q, const CalibrationFile& c) {
  if (q.instrument && c.instrument && *q.instrument != *c.instrument)
    throw UsageError(words("export: {instrument} ") + std::string(instrument_name(*q.instrument)) +
                     " contradicts the " + std::string(instrument_name(*c.instrument)) + " calibration in " +
                     display_name(q.calibration));
  return q.instrument ? *q.instrument : c.instrument ? *c.instrument : Instrument::accel;
}

double number_at(const Json& d, const char* key) {
  return d.contains(key) && d[key].is_number() ? d[key].get<double>() : NAN;
}

Vec3 triple_at(const Json& d, const char* key) {
  Vec3 v = Vec3::Constant(NAN);
  if (d.contains(key) && d[key].is_array() && d[key].size() == 3)
    for (int i = 0; i < 3; ++i)
      if (d[key][static_cast<std::size_t>(i)].is_number()) v(i) = d[key][static_cast<std::size_t>(i)].get<double>();
  return v;
}

std::string text_at(const Json& d, const char* key) {
  return d.contains(key) && d[key].is_string() ? d[key].get<std::string>() : "";
}

// What the file states beside its correction (the c header carries it); what it does not state
// stays NaN (the header writes -1 for a standard error, 0 for a parameter).
CalibrationFacts facts_of(const CalibrationFile& c) {
  const Json& d = c.document;
  CalibrationFacts f;
  f.model = c.model.empty() ? "paper9" : c.model;
  f.sensor = text_at(d, "sensor");
  if (d.contains("tool") && d["tool"].is_object()) {
    const Json& t = d["tool"];
    f.tool = text_at(t, "name") + " " + text_at(t, "version") + ", commit " + text_at(t, "commit");
  } else {
    f.tool = "tool not stated";
  }
  f.magnitude = number_at(d, "magnitude");
  f.nominal_gain = number_at(d, "nominal_gain");
  f.scale_deviation = triple_at(d, "scale_deviation");
  f.nonorthogonality = triple_at(d, "nonorthogonality");
  f.bias_std = triple_at(d, "bias_std");
  f.scale_deviation_std = triple_at(d, "scale_deviation_std");
  f.nonorthogonality_std = triple_at(d, "nonorthogonality_std");
  f.residual_rms = number_at(d, "residual_rms");
  f.positions = static_cast<int>(std::isfinite(number_at(d, "positions")) ? number_at(d, "positions") : 0);
  f.samples = static_cast<int>(std::isfinite(number_at(d, "samples")) ? number_at(d, "samples") : 0);
  return f;
}

ExportInput input_of(const ExportRequest& q, const ExportResult& r) {
  const CalibrationFile& c = r.calibration;
  ExportInput in;
  in.file = c.name;
  in.correction = c.correction;
  in.thermal = c.thermal;
  in.instrument = r.instrument;
  in.units = c.units;
  in.instance = q.instance;
  in.force = q.force;
  in.sample_rate = c.sample_rate;
  in.noise = c.noise;
  in.facts = facts_of(c);
  in.name = q.name;
  if (!q.raw_scale.empty()) {
    in.raw_scale = parse_amount(q.raw_scale);
    if (!in.raw_scale)
      throw UsageError(
          words("export: {raw-scale}: expected a positive size with its unit, such as 0.061mg or 1/16384g, got '") +
          q.raw_scale + "' (units: " + unit_names() + ")");
  }
  in.kept.emplace_back("format_version", std::to_string(kCalibrationFormatVersion));
  for (const char* key : kKept)
    if (c.document.contains(key)) in.kept.emplace_back(key, json_text(c.document[key]));
  if (!c.document.contains("instrument"))
    in.kept.emplace_back("instrument", "\"" + std::string(instrument_name(r.instrument)) + "\"");
  return in;
}

Option instrument_option() {
  Option o = choice_option("--instrument", {"accel", "mag", "gyro"},
                           "the meter: px4 and ardupilot write an accelerometer's offsets and scales, a magnetometer's "
                           "offsets and symmetric matrix, a gyroscope's offsets",
                           "");
  o.fallback_text = "the calibration file's (accel when it names none)";
  return o;
}

}  // namespace

const CommandTable& export_table() {
  Option calibration;
  calibration.name = "CALIBRATION";
  calibration.kind = OptionKind::positional;
  calibration.what = words("a calibration file written by calibrate {out}");
  calibration.takes_document = true;
  static const CommandTable table{
      "export",
      "a calibration file in another tool's form and units: PX4, ArduPilot, IMU-TK, Kalibr/OpenVINS, MATLAB magcal, "
      "a C header for firmware, "
      "or plain JSON",
      72,
      {calibration, choice_option("--format", format_choices(), format_help(), kRequired), instrument_option(),
       named(integer_option("--instance", 0, 4,
                            "px4, ardupilot: which sensor (px4 CAL_ACC0..3, ardupilot INS_ACC, INS_ACC2, INS_ACC3, "
                            "INS4_ACC, INS5_ACC; compasses 0..2)",
                            "index", "0"),
             "N"),
       text_option("--name", "PREFIX",
                   "c: the header's prefix, a C identifier (SCALCAL_PREFIX_OFFSET, scalcal_prefix_apply); CAL when "
                   "not given",
                   "an identifier"),
       text_option("--raw-scale", "SIZE",
                   "what one raw unit (count) of the calibrated log is in a physical unit, e.g. 0.061mg or 1/16384g "
                   "(the driver's scale, from the datasheet): the firmware formats work on the driver's output",
                   "a size with its unit"),
       flag_option("--force",
                   "export a calibration that correct would refuse (not converged, ill-conditioned), or with what "
                   "the target drops above 1 % or a value outside a parameter's documented range"),
       out_option("write the target's file here instead of standard output"),
       json_option("print one JSON object (format, instrument, rotation_rad, dropped_relative, parameters, text)")}};
  return table;
}

ExportRequest export_request(const Values& v) {
  ExportRequest q;
  q.calibration = v.text("CALIBRATION");
  q.format = v.text("--format");
  if (v.given("--instrument")) q.instrument = parse_instrument(v.text("--instrument"));
  q.instance = static_cast<int>(v.integer("--instance"));
  q.force = v.flag("--force");
  q.raw_scale = v.text("--raw-scale");
  q.name = v.text("--name");
  if (const auto it = v.documents.find("CALIBRATION"); it != v.documents.end()) q.calibration_document = it->second;
  return q;
}

ExportResult export_calibration(const ExportRequest& q) {
  const ExportFormat* format = find_export_format(q.format);
  if (!format) throw UsageError(words("export: {format} '") + q.format + "' is not one of " + export_format_names());
  ExportResult r;
  r.request = q;
  r.calibration = q.calibration_document
                      ? calibration_file_of(*q.calibration_document, q.calibration, q.force, r.warnings)
                      : read_calibration_file(q.calibration, q.force, r.warnings);
  if (r.calibration.nonlinear)
    throw InputError(q.calibration, 0,
                     "the " + r.calibration.model +
                         " calibration's correction is nonlinear (a cubic term): no export format carries it");
  r.instrument = instrument_of(q, r.calibration);
  try {
    r.output = export_with(*format, input_of(q, r));
  } catch (const RequestError& e) {
    throw UsageError("export: --" + e.field + ": " + e.what());
  }
  for (const auto& w : r.output.warnings) r.warnings.push_back({q.calibration, w});
  return r;
}

Json to_json(const ExportResult& r) {
  Json parameters = Json::object();
  for (const auto& p : r.output.parameters) parameters[p.name] = p.value;
  return Json{{"format", r.request.format},
              {"instrument", std::string(instrument_name(r.instrument))},
              {"rotation_rad", r.output.rotation_rad},
              {"dropped_relative", r.output.dropped_relative},
              {"parameters", parameters},
              {"text", r.output.text}};
}

}  // namespace scalcal::commands
