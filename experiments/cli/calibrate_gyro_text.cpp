// The text of a gyro's calibration (calibrate_gyro_text.hpp).
#include "experiments/cli/calibrate_gyro_text.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "numeric/criteria/registry.hpp"

namespace scalcal::cli {
namespace {

void correction(std::ostream& s, const commands::GyroCalibrateResult& r, const std::string& unit) {
  s << "correction: physical = matrix (raw - offset), physical in " << unit << "\n";
  s << std::setprecision(10) << "  offset  " << r.offset(0) << ", " << r.offset(1) << ", " << r.offset(2) << "\n";
  for (int a = 0; a < 3; ++a)
    s << (a == 0 ? "  matrix  " : "          ") << r.matrix(a, 0) << ", " << r.matrix(a, 1) << ", " << r.matrix(a, 2)
      << "\n";
}

void scalar(std::ostream& s, const commands::GyroCalibrateResult& r) {
  const auto& c = *r.scalar;
  const bool table = r.method == commands::GyroMethod::rate_table;
  s << r.items.size() << (table ? " constant-rate segments" : " known turns") << " and " << r.rests.size() << " rests";
  if (!table && r.motions_skipped > 0) s << " (" << r.motions_skipped << " other motions between rests not used)";
  s << "\nmodel " << model_name(c.model) << ": " << r.model_reason << "\n";
  static const char* names[9] = {"bias_x", "bias_y",     "bias_z",     "gain_x",    "gain_y",
                                 "gain_z", "nonorth_xy", "nonorth_yz", "nonorth_zx"};
  s << "  parameter          value   standard error\n";
  for (int k = 0; k < 9; ++k) {
    if (std::isnan(c.standard_error(k))) continue;
    s << "  " << std::left << std::setw(11) << names[k] << std::right << std::setprecision(7) << std::setw(14)
      << c.parameters(k) << std::setprecision(3) << std::setw(14) << c.standard_error(k) << "\n";
  }
  s << "  (bias in raw units, gain in raw units per physical unit, nonorth in rad; " << std::setprecision(3)
    << c.item_dof + c.rest_dof << " degrees of freedom, residual variance " << c.item_scale << " x predicted for the "
    << (table ? "segments" : "turns");
  if (!r.rests.empty()) s << ", " << c.rest_scale << " x for the rests";
  s << ")\n";
  if (r.program) {
    s << "program: " << r.program->positions << " directions, condition " << std::setprecision(4)
      << r.program->condition << "; efficiency against the sphere's limit:";
    std::size_t k = 0;
    for (CriterionKind cr : kCriteria) {
      if (k < r.efficiency.size() && std::isfinite(r.efficiency[k]))
        s << " " << criterion_name(cr) << " " << std::setprecision(3) << r.efficiency[k];
      ++k;
    }
    s << "\n";
    for (const Vec3& x : r.suggested)
      s << "  add the table's axis (" << std::setprecision(4) << x(0) << ", " << x(1) << ", " << x(2)
        << ") in the meter's frame, turning counterclockwise about it\n";
  }
}

void hand(std::ostream& s, const commands::GyroCalibrateResult& r) {
  const auto& h = *r.hand;
  const auto& a = *r.accelerometer;
  s << "accelerometer " << a.file << ": model " << model_name(a.model) << ", " << r.poses.size() << " still poses\n";
  s << r.poses.size() << " poses, " << h.misfit.pairs.size() << " rotations between them; misfit "
    << std::setprecision(4) << h.misfit.angle_rms * 180 / M_PI
    << " deg RMS between predicted and measured gravity directions (|R^T g_k - g_k+1| RMS " << h.misfit.chord_rms
    << ")\n";
  const double k = r.matrix(0, 0) / h.matrix(0, 0);
  s << "  matrix entry      value   standard error\n";
  for (int e = 0; e < 9; ++e)
    s << "  C" << e / 3 + 1 << e % 3 + 1 << "     " << std::setprecision(8) << std::setw(15) << r.matrix(e / 3, e % 3)
      << std::setprecision(3) << std::setw(14) << k * h.standard_error(e) << "\n";
  for (int e = 0; e < 3; ++e)
    s << "  offset_"
      << "xyz"[e] << " " << std::setprecision(10) << std::setw(15) << r.offset(e) << std::setprecision(3)
      << std::setw(14) << h.standard_error(9 + e) << "\n";
  if (r.paper_form)
    s << std::setprecision(6) << "  scale " << r.paper_form->scale(0) << ", " << r.paper_form->scale(1) << ", "
      << r.paper_form->scale(2) << " raw per physical unit; nonorthogonality " << std::setprecision(3)
      << r.paper_form->nonorthogonality(0) << ", " << r.paper_form->nonorthogonality(1) << ", "
      << r.paper_form->nonorthogonality(2) << " rad; rotation into the accelerometer's frame "
      << r.rotation.norm() * 180 / M_PI << " deg\n";
  s << std::setprecision(3) << "  residual variance " << h.rotation_scale << " x predicted for the rotations, "
    << h.rest_scale << " x for the poses' mean outputs\n";
}

}  // namespace

std::string calibrate_gyro_text(const commands::GyroCalibrateResult& r) {
  std::ostringstream s;
  s << "gyro " << r.request.file << ": " << commands::gyro_method_name(r.method) << ", " << r.rows << " rows; ";
  if (r.scalar) scalar(s, r);
  if (r.hand) hand(s, r);
  correction(s, r, r.request.physical_units.empty() ? "the --magnitude's unit" : r.request.physical_units);
  if (!r.converged()) s << "not converged\n";
  return s.str();
}

}  // namespace scalcal::cli
