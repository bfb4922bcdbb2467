// `scalcal calibrate --instrument gyro` as a library function: a gyro's calibration from a rate
// table's log (segments of constant rate with rests between: --magnitude RATE|auto|column:NAME,
// optional --latitude for the Earth's rate), from known turns (--turn-angle DEG: the largest motions
// between rests are turns of that angle), or from hand rotations against an accelerometer moved with
// it (--accelerometer ACC_LOG --accelerometer-magnitude G: the accelerometer is calibrated first, as
// `calibrate` does, and the gyro's matrix maps into its corrected frame). physical = matrix (raw -
// offset) in every case. Nothing here prints or writes: warnings are returned as data.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "commands/calibration/calibrate.hpp"
#include "commands/core/json.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/gyro/hand_rotations.hpp"
#include "numeric/gyro/known_modulus.hpp"
#include "numeric/gyro/rate_segments.hpp"

namespace scalcal::commands {

enum class GyroMethod { rate_table, known_turns, hand_rotations };
const char* gyro_method_name(GyroMethod m);

// A rate table's --magnitude: the table's rate, auto (the rate unknown: one gain for the three axes' scale), or
// column:NAME (each row's signed rate from that column of the log).
struct TableRate {
  std::optional<double> rate;  // none: auto, or a column
  std::string column;          // the column's name; "" when the rate is not a column
  bool automatic() const { return !rate && column.empty(); }
};

struct GyroCalibrateRequest {
  std::string file;  // the gyro's log
  LogFormat format = LogFormat::automatic;
  double rate = 0;                       // Hz: row k at k / rate (0: the time column)
  StaticIntervalOptions intervals;       // rests, constant-rate segments (and the accelerometer's poses)
  std::optional<TableRate> magnitude;    // a rate table's; none: not a rate table
  std::optional<double> turn_angle_deg;  // known turns: each turn's angle
  std::string accelerometer;             // hand rotations: the accelerometer's log, same rows as the gyro's
  std::optional<std::optional<double>> accelerometer_magnitude;  // its |g| (none inside: auto); none: not given
  std::optional<double> latitude_deg;             // rate table: add the Earth's rate along the table's axis
  Vec3 table_axis = Vec3::UnitZ();                // that axis in east, north, up (--table-axis), unit length
  std::optional<ModelKind> model;                 // rate table and turns: empty = auto
  std::string sensor, raw_units, physical_units;  // physical: the --magnitude's unit, else rad/s
  Warnings warnings;
};

// From calibrate's options with --instrument gyro (UsageError for an accelerometer's option or a
// contradictory set).
GyroCalibrateRequest gyro_calibrate_request(const Values& values);

// Which method the options name, and UsageError for a contradictory or incomplete set (one line,
// naming the options).
GyroMethod gyro_method(const GyroCalibrateRequest& request);

struct GyroCalibrateResult {
  GyroCalibrateRequest request;
  GyroMethod method = GyroMethod::rate_table;
  int rows = 0;
  IntervalDetection detection;  // of the gyro's log (rate table, turns) or of the accelerometer's (hands)
  // Rate table and turns.
  std::optional<gyro::KnownModulusCalibration> scalar;
  std::string model_reason;
  std::vector<gyro::ModulusItem> items;  // the segments or turns, with their known moduli
  std::vector<gyro::LogInterval> rests;
  int motions_skipped = 0;  // turns: motions between rests that are not known turns (face changes)
  // The segments' or turns' directions judged as a program under the model (Theorem 24: the
  // accelerometer's criteria), each criterion's efficiency against the sphere's limit, and the three
  // positions (table axes, signed by the turn) that improve D most.
  std::optional<ModelEvaluation> program;
  std::vector<double> efficiency;
  std::vector<Vec3> suggested;
  // Hand rotations.
  std::optional<gyro::HandRotationCalibration> hand;
  std::optional<CalibrateResult> accelerometer;
  std::vector<gyro::GyroPose> poses;
  // Every method: the correction, and its paper form (scale factors, non-orthogonality; for hand
  // rotations the rotation into the accelerometer's frame beside them).
  Mat3 matrix = Mat3::Identity();
  Vec3 offset = Vec3::Zero();
  std::optional<FullCorrection> paper_form;
  Vec3 rotation = Vec3::Zero();  // rad, rotation vector of matrix * paper_form.matrix^-1 (hand rotations)
  double noise = NAN;            // one sample's white noise in physical units (the rests' scatter through the matrix)
  Warnings warnings;

  bool converged() const;
  int status() const { return converged() ? 0 : 1; }
};

// InputError for bad files and data that cannot be calibrated, UsageError for options.
GyroCalibrateResult calibrate_gyro(const GyroCalibrateRequest& request);

// The calibration file: the accelerometer's header and keys (offset, matrix, units, ...) with
// "instrument": "gyro", the method, its items and, for hand rotations, the accelerometer's
// calibration under "accelerometer".
Json gyro_calibration_file_json(const GyroCalibrateResult& r);

}  // namespace scalcal::commands
