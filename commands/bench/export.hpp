// `scalcal export` as a function: a calibration file (calibrate --out), physical = matrix
// (raw - offset), written in another tool's form, convention and units. The formats are registered
// in numeric/export (one small type each: json, magcal, imu_tk, kalibr, px4, ardupilot); each says
// there how its target applies the numbers. The instrument comes from the calibration file (an
// explicit one must agree with it); a calibration of a log in counts needs the driver's scale
// (raw_scale, "0.061mg") for the firmware formats, which work on the driver's output in their units.
#pragma once
#include <optional>
#include <string>

#include "commands/calibration/calibration_file.hpp"
#include "commands/core/json.hpp"
#include "commands/core/option_table.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/export/export_format.hpp"

namespace scalcal::commands {

struct ExportRequest {
  std::string calibration;               // the file written by calibrate --out
  std::string format = "json";           // a registered export format
  std::optional<Instrument> instrument;  // empty: the calibration file's (accel when it says none)
  int instance = 0;                      // which sensor of the firmware (px4 CAL_ACC0.., ardupilot INS_ACC, INS_ACC2..)
  bool force = false;                    // export what correct would refuse, or what the target drops
  std::string name;                      // the c header's prefix ("": CAL)
  std::string raw_scale;                 // one raw unit of the log in a physical unit ("0.061mg"); "": the file's units
  std::optional<Json> calibration_document;  // the calibration given as an object (Python), not read
};

struct ExportResult {
  ExportRequest request;
  CalibrationFile calibration;  // as read and checked
  Instrument instrument = Instrument::accel;
  ExportOutput output;  // the target's text, its parameters, what it turns or drops
  Warnings warnings;
};

// CALIBRATION --format NAME [--instrument accel|mag|gyro] [--instance N] [--raw-scale SIZE] [--force]
// [--out FILE] [--json]
const CommandTable& export_table();
ExportRequest export_request(const Values& values);

// InputError for a file that is not a calibration, one correct would refuse (without force), or a
// calibration the target cannot hold (missing units, out of range); UsageError for an option out of
// place (an instrument the format does not have, an instance it lacks, a bad raw scale).
ExportResult export_calibration(const ExportRequest& request);

// format, instrument, rotation_rad, dropped_relative, parameters {name: value}, text
Json to_json(const ExportResult& result);

}  // namespace scalcal::commands
