// `scalcal export` (export.hpp): the calibration read as `correct` reads it, then one writer per target.
#include "commands/export.hpp"

#include <cmath>
#include <cstdio>

#include "commands/common_options.hpp"
#include "commands/correct.hpp"
#include "commands/export_formats.hpp"
#include "commands/usage_error.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::commands {
namespace {

// The metadata a calibration file carries (calibrate --out), kept in the json target.
constexpr const char* kKept[] = {"format_version", "created", "tool",   "sensor",   "units",
                                 "magnitude",      "model",   "region", "converged"};

void write_json(const ExportRequest& q, ExportResult& r) {
  Json doc = Json::object();
  try {
    doc = parse_json_file_text(read_text_file(q.calibration), q.calibration);
  } catch (const InputError&) {  // read_calibration has checked it already
  }
  Json out = Json::object();
  for (const char* key : kKept)
    if (doc.is_object() && doc.contains(key)) out[key] = doc[key];
  out["format_version"] = doc.is_object() && doc.contains("format_version") ? doc["format_version"] : Json(1);
  out["convention"] = "physical = matrix (raw - offset), matrix by rows";
  const Vec3& o = r.correction.offset;
  const Mat3& C = r.correction.matrix;
  out["offset"] = Json{o(0), o(1), o(2)};
  out["matrix"] =
      Json{Json{C(0, 0), C(0, 1), C(0, 2)}, Json{C(1, 0), C(1, 1), C(1, 2)}, Json{C(2, 0), C(2, 1), C(2, 2)}};
  r.text = json_text(out, 2) + "\n";
}

}  // namespace

const CommandTable& export_table() {
  Option calibration;
  calibration.name = "CALIBRATION";
  calibration.kind = OptionKind::positional;
  calibration.what = "a calibration file written by calibrate --out";
  Option format = choice_option("--format", {"json", "magcal", "imu_tk", "kalibr", "px4", "ardupilot"},
                                "the target and its convention (docs/bench.md, Export)", kRequired);
  static const CommandTable table{
      "export",
      "a calibration file in another tool's form: PX4, ArduPilot, IMU-TK, Kalibr, MATLAB magcal, or plain JSON",
      72,
      {calibration, format,
       choice_option("--instrument", {"accel", "mag"},
                     "px4, ardupilot: the accelerometer's parameters (offsets and scales: the non-orthogonality is "
                     "dropped) or the magnetometer's (offsets and a symmetric matrix)",
                     "accel"),
       named(
           integer_option("--instance", 0, 3,
                          "px4, ardupilot: which sensor (px4 CAL_ACC0.., ardupilot INS_ACC, INS_ACC2..)", "index", "0"),
           "N"),
       flag_option("--force", "export a calibration that correct would refuse (not converged, ill-conditioned)"),
       out_option("write the target's file here instead of standard output"),
       json_option("print one JSON object (format, instrument, rotation_rad, dropped_relative, text)")}};
  return table;
}

ExportRequest export_request(const Values& v) {
  ExportRequest q;
  q.calibration = v.text("CALIBRATION");
  q.format = v.text("--format");
  q.instrument = v.text("--instrument");
  q.instance = static_cast<int>(v.integer("--instance"));
  q.force = v.flag("--force");
  return q;
}

ExportResult export_calibration(const ExportRequest& q) {
  ExportResult r;
  r.request = q;
  if (q.instrument != "accel" && q.format != "px4" && q.format != "ardupilot" && q.format != "kalibr")
    throw UsageError("--instrument belongs to --format px4 and ardupilot");
  r.correction = read_calibration(q.calibration, q.force, r.warnings);
  if (q.format == "json")
    write_json(q, r);
  else if (q.format == "magcal")
    write_magcal(q, r);
  else if (q.format == "imu_tk")
    write_imu_tk(q, r);
  else if (q.format == "kalibr")
    write_kalibr(q, r);
  else if (q.format == "px4")
    write_px4(q, r);
  else
    write_ardupilot(q, r);
  char share[64];
  if (r.dropped_relative > 1e-7) {  // beyond a float parameter's precision
    std::snprintf(share, sizeof share, "%.2g", r.dropped_relative);
    r.warnings.push_back(
        {q.calibration, std::string("--format ") + q.format +
                            " has no non-orthogonality terms for an accelerometer: dropping them moves a "
                            "corrected vector by up to " +
                            share + " of its length"});
  }
  return r;
}

Json to_json(const ExportResult& r) {
  return Json{{"format", r.request.format},
              {"instrument", r.request.instrument},
              {"rotation_rad", r.rotation_rad},
              {"dropped_relative", r.dropped_relative},
              {"text", r.text}};
}

}  // namespace scalcal::commands
