// `scalcal export` as a function: a calibration file (calibrate --out), physical = C (raw - o) with
// C its `matrix` and o its `offset`, written in another tool's own form. Each target's formula, as
// that tool applies it (docs/bench.md, "Export"):
//   json       scalcal's convention itself: offset, matrix (rows), with the file's metadata
//   magcal     MATLAB magcal: rows d of raw data, corrected = (d - b) A: A = C^T, b = o^T
//   imu_tk     CalibratedTriad::load's text: X' = T K (X - B), T with a unit diagonal, K diagonal:
//              K = diag(C), T = C K^-1, B = o
//   kalibr     the scale-misalignment model's accelerometer: raw = M a + b with M lower triangular:
//              C^-1 = M R (R a rotation: kalibr keeps it in the IMU's orientation), b = o, and
//              a = R C (raw - o); R is written beside M
//   px4        QGroundControl parameters. accel: CAL_ACCn_{X,Y,Z}OFF = o, CAL_ACCn_{X,Y,Z}SCALE = C_ii,
//              corrected = (raw - OFF) .* SCALE (Accelerometer::Correct): C's off-diagonal terms, the
//              non-orthogonality, cannot be written and are dropped (a warning says how much that
//              moves a corrected vector). mag: corrected = S (raw - OFF) with S symmetric
//              (Magnetometer::Correct): S the symmetric factor of C = Q S, SCALE its diagonal, ODIAG
//              (S01, S02, S12); moduli as C's, vectors turned by Q (a rotation of order gamma^2)
//   ardupilot  parameter file NAME,VALUE. accel: INS_ACC[n]OFFS_* = o, INS_ACC[n]SCAL_* = C_ii,
//              corrected = (raw - OFFS) .* SCAL, off-diagonals dropped as for px4. mag: corrected =
//              M (raw + OFS) (AP_Compass_Backend::correct_field): COMPASS_OFS[n]_* = -o, M = S with
//              COMPASS_DIA[n]_* its diagonal and COMPASS_ODI[n]_* (S01, S02, S12)
// Float parameters (px4, ardupilot) are printed with 9 significant digits (a float32 read back
// exactly); the others with 17 (a double read back exactly).
#pragma once
#include <string>

#include "commands/json.hpp"
#include "commands/option_table.hpp"
#include "commands/values.hpp"
#include "commands/warning.hpp"
#include "numeric/calibration/full_correction.hpp"

namespace scalcal::commands {

struct ExportRequest {
  std::string calibration;           // the file written by calibrate --out
  std::string format = "json";       // json, magcal, imu_tk, kalibr, px4, ardupilot
  std::string instrument = "accel";  // px4, ardupilot: accel or mag
  int instance = 0;                  // px4 CAL_ACC0, ardupilot INS_ACC (0), INS_ACC2 (1), ...
  bool force = false;                // export a calibration correct would refuse, with a warning
};

struct ExportResult {
  ExportRequest request;
  FullCorrection correction;  // as read
  std::string text;           // the target's file
  // How the target's corrected vector differs from scalcal's: the angle of the rotation it turns
  // them by (kalibr, the symmetric soft-iron forms; 0 otherwise), and for the diagonal-only forms
  // the largest relative change the dropped off-diagonal terms make (|C_off v| / |C v| at most).
  double rotation_rad = 0;
  double dropped_relative = 0;
  Warnings warnings;
};

// CALIBRATION --format json|magcal|imu_tk|kalibr|px4|ardupilot [--instrument accel|mag] [--instance N]
// [--force] [--out FILE] [--json]
const CommandTable& export_table();
ExportRequest export_request(const Values& values);

// InputError for a file that is not a calibration or one correct would refuse (without force);
// UsageError for an instrument the format does not have.
ExportResult export_calibration(const ExportRequest& request);

Json to_json(const ExportResult& result);  // format, instrument, rotation_rad, dropped_relative, text

// The symmetric factor S of C = Q S (Q a rotation, S symmetric positive definite): |S v| = |C v|.
Mat3 symmetric_factor(const Mat3& C);

}  // namespace scalcal::commands
