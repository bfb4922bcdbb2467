// What PX4's and ArduPilot's thermal calibrations carry of a thermal fit (docs/thermal_export_sources.md):
// an accelerometer's offset polynomial of degree 3 at most in (T - reference), subtracted before a constant
// offset and a constant diagonal scale, both held at the ends of [TMIN, TMAX]. The scales' and
// non-orthogonalities' drift and the off-diagonal terms are dropped, measured over the fitted range.
#pragma once
#include <string_view>

#include <Eigen/Core>

#include "numeric/export/target_units.hpp"

namespace scalcal {

struct ThermalTarget {
  TargetCorrection at_reference;  // the constant part: offset and matrix at the reference, target units
  Eigen::Matrix<double, 3, Eigen::Dynamic> polynomial;  // column j: offset's coefficient of (T - reference)^j
  double low = 0, high = 0;                             // the fitted range, degC (the firmware's TMIN, TMAX)
};

// Throws RequestError/InputError: a magnetometer's (neither autopilot's thermal offsets are confirmed for
// one), a degree above `max_degree`; check_dropped() on what the target drops.
// The polynomial about `reference` (PX4's TREF, ArduPilot's fixed 35 degC); the constant offset and the
// matrix at `constant_at` (clamped to the range: where the firmware's constant calibration holds).
ThermalTarget thermal_in_target_units(const ExportInput& input, ExportOutput& output, const Unit& target,
                                      std::string_view format, double reference, double constant_at, int max_degree);

}  // namespace scalcal
