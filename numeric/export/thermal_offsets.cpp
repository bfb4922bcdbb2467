// A thermal fit in the autopilots' form: offset polynomial, constant offset and diagonal scale (thermal_offsets.hpp).
#include "numeric/export/thermal_offsets.hpp"

#include <algorithm>

#include "numeric/export/matrix_forms.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal {

ThermalTarget thermal_in_target_units(const ExportInput& in, ExportOutput& out, const Unit& target,
                                      std::string_view format, double reference, double constant_at, int max_degree) {
  const ThermalCorrection& th = *in.thermal;
  const std::string name(format);
  if (in.instrument != Instrument::accel)
    throw InputError(in.file, 0,
                     "the " + name +
                         " export writes an accelerometer's thermal offsets only: where PX4 applies a magnetometer's "
                         "TC_M offsets beside its soft-iron matrix is not confirmed from its source, and ArduPilot has "
                         "no compass temperature calibration (docs/thermal_export_sources.md)");
  if (th.model.degree > max_degree)
    throw InputError(in.file, 0,
                     "its offsets are polynomials of degree " + std::to_string(th.model.degree) + " (" +
                         th.model.name() + "); " + name + " stores degree " + std::to_string(max_degree) +
                         " at most: calibrate with " + std::string(model_name(th.model.base)) + "+T3 or " +
                         std::string(model_name(th.model.base)) + "+bias:T3");
  ExportInput at = in;
  at.correction = th.at(constant_at);
  ThermalTarget t;
  t.at_reference = in_target_units(at, target, format);
  t.polynomial = Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, max_degree + 1);
  t.polynomial.leftCols(th.model.degree + 1) = t.at_reference.raw_unit * th.offset_polynomial(reference);
  t.low = th.range.low;
  t.high = th.range.high;
  // The firmware's matrix is diag(C(reference)) at every temperature: what it drops over the range.
  const double per_raw = t.at_reference.per_physical / t.at_reference.raw_unit;
  const Mat3 kept = t.at_reference.matrix.diagonal().asDiagonal();
  double share = 0;
  for (int i = 0; i <= 100; ++i)
    share = std::max(share, dropped_share(per_raw * th.at(t.low + (t.high - t.low) * i / 100).matrix, kept));
  check_dropped(in, out, format,
                "the scale factors' and non-orthogonalities' temperature drift and the off-diagonal terms (its "
                "thermal parameters are offsets; its scales constant and diagonal)",
                share);
  return t;
}

}  // namespace scalcal
