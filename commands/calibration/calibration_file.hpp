// The one reader of calibration files (`calibrate --out`, or written by hand), for `correct`,
// `export` and the Python module: it checks what the file says of itself before anything is applied
// or converted. Refused (InputError naming the file): a format_version that is not a known integer;
// a key twice in one object (the JSON parser would keep the last silently); nesting deeper than
// kMaxJsonDepth; a missing or ill-typed offset or matrix; a number that is not finite; a model that
// is not registered, or parameters that are not that model's; an instrument or a unit scalcal does
// not know; physical units that contradict the file's own magnitude; a singular matrix (by its
// condition, not its determinant, which underflows for a matrix of 1e-300). Refused unless `force`
// (then a warning as data): a fit that did not converge, a matrix whose condition exceeds
// kCorrectionCondition. A file without "converged" or "format_version" (written by hand) is taken at
// its word; a file of version 1 (before units were recorded) has its units as not given.
#pragma once
#include <optional>
#include <string>

#include "commands/core/json.hpp"
#include "commands/core/warning.hpp"
#include "numeric/export/export_format.hpp"
#include "numeric/thermal/thermal_correction.hpp"

namespace scalcal::commands {

// The calibration file's format: 1 is the first with a version (issue 32); 2 records the instrument
// and the units as units (issue 49).
inline constexpr int kCalibrationFormatVersion = 2;

// Above this condition number of the correction's 3x3 matrix the axes' gains differ by that factor
// or two axes are nearly parallel: no sensor of this kind is built so, a failed fit is.
inline constexpr double kCorrectionCondition = 100;
// Above this condition the matrix is singular to double precision (nothing could be recovered).
inline constexpr double kSingularCondition = 1e12;

struct CalibrationFile {
  std::string name;                      // for messages
  Json document;                         // as read (keys checked)
  int format_version = 0;                // 0: not said (a hand-written file)
  std::string model;                     // empty when not said
  bool nonlinear = false;                // the model has terms the 3x3 correction cannot apply (cubic12)
  FullCorrection correction;             // physical = matrix (raw - offset); identity matrix when nonlinear
  std::optional<Instrument> instrument;  // empty when the file does not say
  CalibrationUnits units;
  double sample_rate = NAN;  // Hz, of a raw log
  double noise = NAN;        // one sample's noise in physical units
  // A thermal model's calibration (calibrate --model BASE+Tk --out): the correction at each
  // temperature; `correction` then holds the one at the range's middle (for messages and checks only).
  std::optional<ThermalCorrection> thermal;
};

// Reads and checks; `force` accepts a fit that did not converge or an ill-conditioned matrix.
CalibrationFile read_calibration_file(const std::string& path, bool force, Warnings& warnings);
// The same checks on a document already parsed (Python gives a dict). `text`, when not empty, is
// the document's source, checked for duplicate keys.
CalibrationFile calibration_file_of(const Json& document, const std::string& name, bool force, Warnings& warnings);

// The units the file records: "raw", "physical" as written by calibrate (issue 49).
Json units_json(const CalibrationUnits& units, bool raw_counts);

}  // namespace scalcal::commands
