// `scalcal correct` as a library function: a calibration file written by `calibrate --out` applied
// to raw data, physical = matrix (raw - offset), row by row; a thermal one (BASE+Tk) at each row's
// temperature (a column temp, temperature or t_c), held at its range's ends outside it as PX4 and
// ArduPilot hold theirs (a warning counts those rows). A calibration that cannot be trusted is
// refused (InputError naming the reason): a fit that did not converge, a matrix that is singular or
// ill-conditioned; `force` applies it all the same, with a warning as data.
#pragma once
#include <string>
#include <vector>

#include <optional>

#include "commands/calibration/calibration_file.hpp"
#include "commands/core/json.hpp"
#include "commands/core/option_table.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/calibration/full_correction.hpp"
#include "numeric/calibration/raw_log.hpp"
#include "numeric/io/csv_table.hpp"

namespace scalcal::commands {

struct CorrectRequest {
  std::string calibration;  // the file written by `calibrate --out`
  std::string file;         // the raw data
  LogFormat format = LogFormat::automatic;
  bool force = false;                        // apply a calibration that would be refused, with a warning
  std::optional<Json> calibration_document;  // the calibration given as an object (Python), not read
  std::optional<CsvTable> table;             // the raw data given as columns (Python), not read
};

struct CorrectedRow {
  double t = NAN, position = NAN;  // the kept columns (NaN when the file has none)
  double celsius = NAN;            // a thermal calibration's: the row's temperature as the data gave it
  std::string position_label;      // the position's text label (P1), when it has one
  Vec3 corrected = Vec3::Zero();
  double modulus = 0;
};

struct CorrectResult {
  FullCorrection correction;
  bool has_t = false, has_position = false;
  bool has_temperature = false;  // a thermal calibration was applied at each row's temperature
  std::vector<CorrectedRow> rows;
  Warnings warnings;
};

// The correction a checked calibration file applies (commands/calibration/calibration_file.hpp); InputError for a
// nonlinear model's, which a 3x3 correction cannot apply.
FullCorrection linear_correction(const CalibrationFile& calibration);

// --calibration CAL.json --measurements FILE [--format auto|csv|text] [--force] [--out FILE]
const CommandTable& correct_table();
CorrectRequest correct_request(const Values& values);

CorrectResult correct(const CorrectRequest& request);

// The corrected columns: t and position when the data had them, x, y, z, modulus.
Json to_json(const CorrectResult& result);

}  // namespace scalcal::commands
