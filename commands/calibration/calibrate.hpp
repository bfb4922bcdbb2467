// `scalcal calibrate` as a library function: the scalar calibration of one meter from bench data
// (samples grouped by position) or a raw log (its static intervals), in any units, with the model
// the layout can carry (--model auto), the standard errors both ways (noise within positions,
// residuals between them), each position's residual, the measured program's quality and the
// positions worth adding. Nothing here prints or writes: warnings are returned as data.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands/calibration/thermal_calibrate.hpp"
#include "commands/core/option_table.hpp"
#include "commands/core/progress.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/calibration/adaptive_detection.hpp"
#include "numeric/calibration/any_units.hpp"
#include "numeric/calibration/calibration_stream.hpp"
#include "numeric/calibration/instrument.hpp"
#include "numeric/calibration/log_motion.hpp"
#include "numeric/calibration/outlier_samples.hpp"
#include "numeric/calibration/raw_log.hpp"
#include "numeric/calibration/static_intervals.hpp"
#include "numeric/calibration/tumbling.hpp"
#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/export/export_format.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal::commands {

inline constexpr int kMaxSuggestions = 100;  // positions to suggest adding, at most
inline constexpr double kOutlierSigmas = 5;  // a position's standardised residual above this is flagged

// --weights: each position's weight in the least squares, by its samples (the paper's bench data) or one each (a
// raw log's poses: how long the meter was held still says nothing about a position's worth).
enum class PositionWeights { samples, positions };

struct CalibrateRequest {
  std::string file;                 // the data's name in messages (and the file calibrate(request) reads)
  std::optional<double> magnitude;  // |I| in physical units; none: auto (the correction maps the field to modulus 1)
  Modulus modulus = Modulus::norm;
  LogFormat format = LogFormat::automatic;  // of the file
  double rate = 0;                          // Hz: a raw log whose row k is at k / rate (0: its time column)
  StaticIntervalOptions intervals;          // for a raw log
  bool intervals_given = false;            // --window, --threshold-factor, --min-interval or --still given: no choosing
  int chunk_rows = 0;                      // --chunk: a raw log taken in chunks of this many rows (0: whole)
  std::optional<PositionWeights> weights;  // none: auto (a raw log's positions count once each, bench data by samples)
  bool keep_outliers = false;
  int suggest = 3;  // positions to suggest adding
  CriterionKind criterion = CriterionKind::D;
  std::vector<std::string> regions;       // where positions may be added: --region, else the region line of --program
                                          // or of the measurements file; none: the sphere
  std::string program;                    // --program: the program the data measured (its region line is used)
  double tolerance_deg = 0.05;            // a measured position this far outside the region still counts as inside
  std::string sensor;                     // --sensor: a label for the calibration file
  std::string raw_units, physical_units;  // --units RAW,PHYSICAL for the calibration file ("": not given), checked
  std::optional<Instrument> instrument;   // empty: from the log (a tumbling log whose modulus survives the
                                          // motion is a magnetometer's) and the magnitude
  Warnings warnings;                      // found while reading the request
  std::optional<ModelKind> model;         // empty: auto, the richest linear model the layout carries
  std::optional<CsvTable> table;          // the data given as columns (Python), instead of reading `file`
  std::optional<ThermalModel>
      thermal;  // --model BASE+Tk: a thermal log's fit (commands/calibration/thermal_calibrate.hpp)
  std::optional<TemperatureRange> temperature;  // --temperature: tau's interval (default: the poses' span)
};

// What the data held: positions, and for a raw log how they were found.
struct CalibrationInput {
  std::vector<PositionSamples> data;
  std::optional<RawLog> log;
  IntervalDetection detection;
  LogMotion motion;                       // a raw log's: its noise, how much it moves, the modulus in motion
  std::optional<DetectionChoice> chosen;  // the detection chosen for this log (adaptive_detection.hpp)
  int chunks = 0;                         // the chunks the log's stream took (1: the whole log at once)
  bool every_sample = false;              // a tumbling log: every usable sample is a position
  std::vector<int> sample_index;          // with every_sample: each position's sample in the log
  std::optional<Instrument> instrument;   // as given or as the log shows it; empty when neither says
  std::string instrument_reason;          // why, one sentence
  Warnings warnings;                      // dropouts and saturated samples of a raw log
};

// One measured position as a bench engineer reads it.
struct PositionResult {
  int line = 0;                   // its first sample's line
  double start = NAN, end = NAN;  // a raw log's interval, seconds (NaN for bench data)
  int samples = 0;
  Vec3 mean = Vec3::Zero();          // raw, file units
  Vec3 direction = Vec3::Zero();     // unit vector in the meter's frame after calibration
  double residual = 0;               // |corrected mean| - |I|, physical units (|I| = 1 with magnitude auto)
  double standardised_residual = 0;  // by the residuals' own scale and the position's leverage
};

struct SuggestedAddition {
  Vec3 position = Vec3::Zero();  // the field's direction in the meter's frame
  double value = 0;              // the criterion with this and every earlier suggestion added
  std::vector<double> errors;    // sqrt(max K(r,r)) per parameter group of the model, not normalised by N
};

// The measured program judged under the chosen model.
struct ProgramQuality {
  ModelEvaluation evaluation;
  std::string region;              // the region the efficiencies and suggestions refer to
  std::vector<double> efficiency;  // per registered criterion (NaN: no known limit)
  std::vector<SuggestedAddition> suggested;
};

// A tumbling log's fit: what was left out, how well it covered the sphere, how correlated its
// residuals are in time.
struct TumblingReport {
  std::vector<DisturbedStretch> disturbed;  // left out, in time order
  int samples_used = 0;
  Coverage coverage;
  double noise = NAN;               // one sample's noise from second differences, physical units
  double correlation_factor = NAN;  // Newey-West standard error / the independent-residual one (largest)
  int lag = 0;                      // samples of the Newey-West window
};

struct CalibrateResult {
  std::string file;
  CalibrateRequest request;
  std::optional<Instrument> instrument;  // the meter, as given or as the log shows it
  std::string instrument_reason;
  CalibrationUnits units;                  // of the calibration (calibration file's "units")
  bool raw_counts = false;                 // the raw units are counts (said with --units)
  std::string units_reason;                // how the units were known
  std::optional<LogMotion> motion;         // a raw log's
  std::optional<TumblingReport> tumbling;  // a tumbling log's fit
  bool weight_by_samples = true;
  ModelKind model = ModelKind::paper9;
  std::string model_reason;                   // why this model (auto), or "requested"
  std::vector<std::string> not_identifiable;  // what the layout or the data cannot determine
  std::string not_estimated;                  // what the model itself leaves out, one sentence
  AnyUnitsCalibration fit;
  double field_strength = NAN;      // --magnitude auto: |I| in file units (gain's geometric mean)
  double field_strength_std = NAN;  // its standard error
  std::vector<PositionResult> positions;
  std::vector<int> outliers;  // indices into positions, |standardised| > kOutlierSigmas, worst first
  std::vector<ExcludedSample> excluded;
  std::optional<IntervalDetection> detection;  // a raw log's
  std::optional<DetectionChoice> chosen;       // how its detection was chosen
  int rows = 0;                                // a raw log's rows
  int chunk_rows = 0, chunks = 0;              // --chunk: the stream's chunk and how many it took (0: whole)
  double sample_rate = NAN;                    // a raw log's, Hz
  ProgramQuality program;
  double t95 = NAN;                                   // Student's t at 97.5 % for dof (95 % two-sided), NaN for dof < 1
  std::shared_ptr<const ThermalCalibration> thermal;  // a thermal model's calibration (then the rest is empty)
  Warnings warnings;

  bool converged() const {
    return thermal ? thermal->fit.converged && thermal->fit.problem.empty() : fit.estimate.summary.converged();
  }
  int status() const { return converged() ? 0 : 1; }  // the CLI's exit status
};

// Why a --magnitude text is refused ("" when it is a positive number or "auto"), and the value it gives (none: auto).
std::string magnitude_problem(const std::string& magnitude);
std::string magnitude_problem(const std::optional<double>& magnitude);  // a typed one (none: auto)
std::optional<double> magnitude_value(const std::string& magnitude);
// A magnitude as the reports quote it: the shortest text that reads back to it, or "auto".
std::string magnitude_text(const std::optional<double>& magnitude);
// UsageError for a bad magnitude or options the model does not take (checked before any file is read).
void check_calibrate_request(const CalibrateRequest& request);
// From request.file: grouped samples (strict CSV) or a raw log (a time column, a text log, or
// request.rate). InputError for a bad file.
CalibrationInput read_calibration_input(const CalibrateRequest& request);
// From a raw log: its static intervals become positions; InputError when too few are found (the
// message says what would help for this log), warnings for dropouts and saturation.
CalibrationInput calibration_input(RawLog log, const CalibrateRequest& request);
// The same from a stream's poses so far (the log's own options are the stream's; the request's are ignored).
CalibrationInput calibration_input(const CalibrationStream& stream, const CalibrateRequest& request);

// --measurements FILE --magnitude M|auto [--model auto|NAME] [--modulus ...] [--format ...] [--rate HZ] [--still S]
// [--window W] [--threshold-factor K] [--min-interval T] [--weights ...] [--keep-outliers] [--suggest K]
// [--criterion C] [--region SPEC]... [--program FILE] [--tolerance DEG] [--sensor LABEL] [--units RAW,PHYSICAL]
// [--out FILE] [--json]
const CommandTable& calibrate_table();
CalibrateRequest calibrate_request(const Values& values);
// The raw log's options (--format, --rate, --still, --window, --threshold-factor, --min-interval), read
// alike for an accelerometer's log and a gyro's (calibrate_gyro_request).
void read_log_options(const Values& values, LogFormat& format, double& rate, StaticIntervalOptions& intervals);

// UsageError: an explicit model the layout cannot carry (naming the parameters and the model that
// would work). InputError: data that cannot be calibrated, or a fit that is not finite.
CalibrateResult calibrate(const CalibrateRequest& request, CalibrationInput input, const Progress& progress = {});
CalibrateResult calibrate(const CalibrateRequest& request, const Progress& progress = {});

}  // namespace scalcal::commands
