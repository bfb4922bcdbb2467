// What every firmware format needs: the calibration in the target's units, and the checks of what
// the target can hold. A firmware corrects the driver's output v (already in the target's units,
// v = s raw for a raw unit worth s target units) as corrected = matrix_t (v - offset_t); scalcal's
// physical = C (raw - o) is k target units per physical unit, so matrix_t = k C / s and
// offset_t = s o. With --magnitude auto the physical unit is the field's strength F (raw units):
// a magnetometer's target then keeps the driver's own scale, k = F s, and matrix_t = F C has
// geometric-mean gain 1 (what PX4 and ArduPilot store: scales near 1).
#pragma once
#include <string>
#include <string_view>

#include "numeric/export/export_format.hpp"

namespace scalcal {

struct TargetCorrection {
  Mat3 matrix = Mat3::Identity();  // target units per target unit of the driver's output
  Vec3 offset = Vec3::Zero();      // target units
  double raw_unit = 1;             // s: one raw unit in target units
  double per_physical = 1;         // k: one physical unit of the calibration in target units
};

// Throws InputError saying what is missing: the raw units' size (--raw-scale), the physical units
// (calibrate --units), or a gain that --magnitude auto left unknown.
TargetCorrection in_target_units(const ExportInput& input, const Unit& target, std::string_view format);

// A value a float32 parameter can hold: finite, below 3.4e38, and zero or above 1.2e-38 (a smaller
// one would be stored as a subnormal or zero). Throws InputError naming the parameter.
void check_float32(const ExportInput& input, std::string_view parameter, double value);
// A value inside the range the target documents (source: where the range is written down); outside
// it is refused unless input.force (then a warning is added).
void check_range(const ExportInput& input, ExportOutput& output, std::string_view parameter, double value, double low,
                 double high, std::string_view source);
// The target drops a share of the corrected vector (off-diagonal terms, a rotation): beyond
// kDroppedTolerance refused unless forced (or `refuse` is false: a target that never carries it, such
// as a firmware's gyro offsets without scales); above float precision a warning saying how much.
void check_dropped(const ExportInput& input, ExportOutput& output, std::string_view format, std::string_view what,
                   double share, bool refuse = true);
// A magnetometer's symmetric form S of C = Q S (PX4's and ArduPilot's soft iron): Q turns the
// corrected vectors from scalcal's convention to the symmetric one, which scalar calibration cannot
// tell apart (a warning says by how much); a rotation C holds beyond the convention (a mounting) is
// lost, and refused beyond kDroppedTolerance unless forced. Returns S.
Mat3 symmetric_form(const ExportInput& input, ExportOutput& output, std::string_view format, const Mat3& C);
// The instance is one the target has (0 .. count - 1).
void check_instance(const ExportInput& input, std::string_view format, int count);

// Number texts: 17 significant digits (a double reads back exactly), 9 (a float32 does).
std::string exact_text(double v);
std::string float_text(double v);

}  // namespace scalcal
