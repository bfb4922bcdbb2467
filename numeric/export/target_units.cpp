// The calibration in a target's units and the checks of what a target holds (target_units.hpp).
#include "numeric/export/target_units.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>

#include "numeric/export/matrix_forms.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal {
namespace {

std::string short_text(double v) {
  char s[40];
  std::snprintf(s, sizeof s, "%.4g", v);
  return s;
}

// s: one raw unit in target units.
double raw_unit_in(const ExportInput& in, const Unit& target, std::string_view format) {
  const std::string quantity(quantity_name(target.quantity));
  if (in.raw_scale) {
    if (in.raw_scale->unit.quantity != target.quantity)
      throw InputError(in.file, 0,
                       "the raw scale is in " + std::string(in.raw_scale->unit.name) + ", not a unit of " + quantity +
                           " as the " + std::string(format) + " export needs for a " +
                           std::string(instrument_noun(in.instrument)));
    return in.raw_scale->value * factor(in.raw_scale->unit, target);
  }
  if (in.units.raw) {
    if (in.units.raw->quantity != target.quantity)
      throw InputError(in.file, 0,
                       "its raw units " + std::string(in.units.raw->name) + " are not a unit of " + quantity + " (a " +
                           std::string(instrument_noun(in.instrument)) + "'s calibration?)");
    return factor(*in.units.raw, target);
  }
  throw InputError(in.file, 0,
                   "the " + std::string(format) + " export applies the calibration to the driver's output in " +
                       std::string(target.name) +
                       ", and the calibration does not say what one raw unit of its log is (raw units counts or not "
                       "given): give the driver's scale, e.g. raw scale 0.061mg per count (the sensor's datasheet), "
                       "or calibrate a log in physical units");
}

}  // namespace

TargetCorrection in_target_units(const ExportInput& in, const Unit& target, std::string_view format) {
  TargetCorrection t;
  t.raw_unit = raw_unit_in(in, target, format);
  double k = 0;  // target units per physical unit
  if (in.units.unit_modulus) {
    if (in.instrument != Instrument::mag)
      throw InputError(in.file, 0,
                       "it was calibrated with the magnitude unknown (auto), which leaves the " +
                           std::string(instrument_noun(in.instrument)) + words("'s gain unknown; {format} ") +
                           std::string(format) + " needs it: calibrate with the known magnitude");
    if (!(in.units.field_strength > 0))
      throw InputError(in.file, 0,
                       "it has the magnitude unknown (auto) but no field_strength to scale the correction back by");
    k = in.units.field_strength * t.raw_unit;
  } else if (in.units.physical) {
    if (in.units.physical->quantity != target.quantity)
      throw InputError(in.file, 0,
                       "its physical units " + std::string(in.units.physical->name) + " are not a unit of " +
                           std::string(quantity_name(target.quantity)) + " as a " +
                           std::string(instrument_noun(in.instrument)) + "'s are");
    k = factor(*in.units.physical, target);
  } else {
    throw InputError(
        in.file, 0,
        "the " + std::string(format) +
            " export needs the calibration's physical units and it names none: "
            "calibrate with its units given (raw and physical, e.g. counts,m/s^2), or with a magnitude whose "
            "units the Earth fixes (9.81 m/s^2, 1 g, 50 uT)");
  }
  t.per_physical = k;
  t.matrix = (k / t.raw_unit) * in.correction.matrix;
  t.offset = t.raw_unit * in.correction.offset;
  return t;
}

void check_float32(const ExportInput& in, std::string_view parameter, double v) {
  if (!std::isfinite(v))
    throw InputError(in.file, 0,
                     std::string(parameter) + " would be " + short_text(v) + ": not a number a target holds");
  if (std::abs(v) > FLT_MAX)
    throw InputError(
        in.file, 0,
        std::string(parameter) + " would be " + short_text(v) + ", beyond a float32 parameter's range (3.4e38)");
  if (v != 0 && std::abs(v) < FLT_MIN)
    throw InputError(in.file, 0,
                     std::string(parameter) + " would be " + short_text(v) +
                         ", below a float32 parameter's normal range (1.2e-38): it would be stored as another number");
}

void check_range(const ExportInput& in, ExportOutput& out, std::string_view parameter, double v, double low,
                 double high, std::string_view source) {
  if (v >= low && v <= high) return;
  const std::string why = std::string(parameter) + " = " + short_text(v) + " is outside its range " + short_text(low) +
                          " .. " + short_text(high) + " (" + std::string(source) + ")";
  if (!in.force) throw InputError(in.file, 0, why + "; force writes it all the same");
  out.warnings.push_back("written although " + why);
}

void check_dropped(const ExportInput& in, ExportOutput& out, std::string_view format, std::string_view what,
                   double share, bool refuse) {
  out.dropped_relative = std::max(out.dropped_relative, share);
  if (!(share > 1e-7)) return;  // below a float parameter's precision
  const std::string text = "the " + std::string(format) + " export cannot carry " + std::string(what) +
                           ": dropping it changes a corrected vector by up to " + short_text(100 * share) +
                           " % of its length";
  if (refuse && share > kDroppedTolerance && !in.force)
    throw InputError(in.file, 0,
                     text + " (more than " + short_text(100 * kDroppedTolerance) +
                         " %: a wrong matrix?); force writes it all the same");
  out.warnings.push_back(text);
}

Mat3 symmetric_form(const ExportInput& in, ExportOutput& out, std::string_view format, const Mat3& C) {
  const Mat3 S = symmetric_factor(C);
  out.rotation_rad = rotation_angle(C * S.inverse());
  const double beyond = rotation_beyond_convention(C);
  // A rotation by theta moves a vector by 2 sin(theta / 2) of its length.
  check_dropped(in, out, format, "a rotation of the axes beyond scalar calibration's convention (a mounting?)",
                std::isfinite(beyond) ? 2 * std::sin(beyond / 2) : 1.0);
  if (out.rotation_rad > 1e-7)
    out.warnings.push_back("the " + std::string(format) + " export's symmetric matrix turns corrected vectors by " +
                           short_text(out.rotation_rad * 180 / M_PI) +
                           " degrees from scalcal's convention: scalar calibration determines the moduli, not this "
                           "rotation, so both are the calibration");
  return S;
}

void check_instance(const ExportInput& in, std::string_view format, int count) {
  if (in.instance < 0 || in.instance >= count)
    throw RequestError("instance", "the " + std::string(format) + " export has " + std::to_string(count) + " " +
                                       std::string(instrument_noun(in.instrument)) + " instances (0 .. " +
                                       std::to_string(count - 1) + "), not " + std::to_string(in.instance));
}

std::string exact_text(double v) {
  char s[40];
  std::snprintf(s, sizeof s, "%.17g", v == 0 ? 0.0 : v);
  return s;
}

std::string float_text(double v) {
  char s[40];
  std::snprintf(s, sizeof s, "%.9g", v == 0 ? 0.0 : v);
  return s;
}

}  // namespace scalcal
