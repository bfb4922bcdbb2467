// An export format of `scalcal export`: one small type per target (a firmware's parameters, another
// tool's file), known everywhere once it has its registration line in registry.cpp. A format takes
// a calibration, physical = matrix (raw - offset) with its instrument and units, and writes the
// target's text in the target's own convention and units, or refuses with one line saying what is
// missing (InputError naming the calibration file) or which option is out of place (RequestError).
// What a target cannot carry is measured (the share of a corrected vector it would change) and,
// beyond kDroppedTolerance, refused unless `force`.
#pragma once
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "numeric/calibration/full_correction.hpp"
#include "numeric/calibration/instrument.hpp"
#include "numeric/calibration/units.hpp"
#include "numeric/thermal/thermal_correction.hpp"

namespace scalcal {

// A share of the corrected vector a target drops (non-orthogonality, a rotation) beyond which the
// export is refused unless forced: 1 % of the measured vector is far beyond any sensor's
// non-orthogonality (about 0.1 % for MEMS parts) and is what a wrong matrix looks like.
inline constexpr double kDroppedTolerance = 1e-2;

// A calibration's units: the log's raw units and those of matrix (raw - offset).
struct CalibrationUnits {
  std::optional<Unit> raw;       // the log's units when they are a physical unit
  bool raw_counts = false;       // the file says the raw units are counts (their size not known)
  std::optional<Unit> physical;  // of the corrected output; empty when not known or with unit_modulus
  bool unit_modulus = false;     // --magnitude auto: the correction maps the field to modulus 1
  double field_strength = NAN;   // with unit_modulus: the field's strength in raw units
};

// What a calibration file states beside its correction, for the formats that carry it (c).
struct CalibrationFacts {
  std::string model, sensor, tool;  // tool: "scalcal VERSION, commit ..."
  double magnitude = NAN;           // |I| in physical units (1 with magnitude auto)
  double nominal_gain = NAN;        // raw units per physical unit (the field's strength with magnitude auto)
  Vec3 scale_deviation = Vec3::Constant(NAN), nonorthogonality = Vec3::Constant(NAN);
  Vec3 bias_std = Vec3::Constant(NAN), scale_deviation_std = Vec3::Constant(NAN),
       nonorthogonality_std = Vec3::Constant(NAN);
  double residual_rms = NAN;
  int positions = 0, samples = 0;
};

struct ExportInput {
  std::string file;  // the calibration's name, for messages
  FullCorrection correction;
  Instrument instrument = Instrument::accel;
  CalibrationUnits units;
  std::optional<Amount> raw_scale;  // what one raw unit (count) of the log is in a physical unit
  int instance = 0;                 // which sensor of the firmware (PX4 CAL_ACC0.., ArduPilot INS_ACC, INS_ACC2..)
  bool force = false;               // write what the target drops beyond kDroppedTolerance, or a documented range
  double sample_rate = NAN;         // Hz, of the log (for formats that state it)
  double noise = NAN;               // one sample's noise in physical units (for formats that state it)
  // For the json format: the calibration file's own keys to keep, each as its JSON text.
  std::vector<std::pair<std::string, std::string>> kept;
  CalibrationFacts facts;  // for the c format
  std::string name;        // the c format's prefix (an identifier; "" : CAL)
  // A thermal fit (BASE+Tk): correction is then the one at the range's middle; only formats that carry
  // temperature drift (ExportFormat::thermal) take it.
  std::optional<ThermalCorrection> thermal;
};

// One parameter as the target stores it, for tests and the JSON of the result.
struct ExportParameter {
  std::string name;
  double value = 0;
};

struct ExportOutput {
  std::string text;
  std::vector<ExportParameter> parameters;  // firmware formats: what the file sets
  double rotation_rad = 0;                  // the rotation the target's form turns corrected vectors by
  double dropped_relative = 0;              // the largest share of a corrected vector the target drops
  std::vector<std::string> warnings;
};

// An option out of place for a format (the front end names it its own way: --instance, instance=).
struct RequestError : std::invalid_argument {
  RequestError(std::string field_name, const std::string& reason)
      : std::invalid_argument(reason), field(std::move(field_name)) {}
  std::string field;
};

struct ExportFormat {
  std::string_view name;  // the --format word
  std::string_view what;  // one line for --help and docs
  std::vector<Instrument> instruments;
  void (*write)(const ExportInput&, ExportOutput&);
  bool thermal;  // writes a thermal fit's offset polynomials (the firmware's thermal parameters)
};

// Every registered format, in registration order (registry.cpp).
const std::vector<ExportFormat>& export_formats();
// The format of this name, or nullptr.
const ExportFormat* find_export_format(std::string_view name);
// "json, magcal, ..." for messages.
std::string export_format_names();

// Runs the format: checks the instrument is one it carries, writes, and checks that every number
// written is finite. Throws InputError, RequestError.
ExportOutput export_with(const ExportFormat& format, const ExportInput& input);

}  // namespace scalcal
