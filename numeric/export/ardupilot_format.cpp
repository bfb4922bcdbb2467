// The ardupilot target: a parameter file of NAME,VALUE lines. Accelerometer (m/s^2):
// corrected = (v - OFFS) .* SCAL (AP_InertialSensor_Backend::_rotate_and_correct_accel), instances
// INS_ACC, INS_ACC2, INS_ACC3, INS4_ACC, INS5_ACC; ranges OFFS -3.5 .. 3.5, SCAL 0.8 .. 1.2
// (AP_InertialSensor.cpp). Magnetometer (milligauss): corrected = M (v + OFS) with M symmetric
// (AP_Compass_Backend::correct_field): OFS = -offset, M = the symmetric factor of C, DIA its
// diagonal and ODI (M01, M02, M12); instances COMPASS_OFS, OFS2, OFS3; OFS -400 .. 400
// (AP_Compass.cpp), DIA 0.2 .. 5 and |ODI| < 1 (CompassCalibrator::fit_acceptable). Gyroscope
// (rad/s): gyro -= GYROFFS, offsets only. A thermal fit (BASE+Tk, k <= 3) adds the accelerometer's
// INS_TCALn_ACC1..3 (10^-6 units, about a fixed 35 degC, no constant term, zero at INS_ACCn_CALTEMP:
// AP_InertialSensor_tempcal.cpp, docs/thermal_export_sources.md).
#include <algorithm>

#include "numeric/export/formats.hpp"
#include "numeric/export/matrix_forms.hpp"
#include "numeric/export/target_units.hpp"
#include "numeric/export/thermal_offsets.hpp"

namespace scalcal {
namespace {

const char* const kAxes[3] = {"X", "Y", "Z"};

// INS_ACC, INS_ACC2, INS_ACC3, then the groups INS4_ and INS5_ (ArduPilot 4.5 and later).
std::string ins_prefix(int instance, const std::string& kind) {
  if (instance == 0) return "INS_" + kind;
  if (instance < 3) return "INS_" + kind + std::to_string(instance + 1);
  return "INS" + std::to_string(instance + 1) + "_" + kind;
}

struct Writer {
  const ExportInput& in;
  ExportOutput& out;
  std::string text;
  void param(const std::string& name, double v) {
    check_float32(in, name, v);
    text += name + "," + float_text(v) + "\n";
    out.parameters.push_back({name, v});
  }
};

void write_accel(const ExportInput& in, ExportOutput& out, Writer& w) {
  check_instance(in, "ardupilot", 5);
  const TargetCorrection t = in_target_units(in, *parse_unit("m/s^2"), "ardupilot");
  check_dropped(in, out, "ardupilot", "an accelerometer's non-orthogonality (off-diagonal terms)",
                dropped_share(t.matrix, Mat3(t.matrix.diagonal().asDiagonal())));
  const std::string p = ins_prefix(in.instance, "ACC");
  w.text += "# corrected = (v - " + p + "OFFS_?) .* " + p + "SCAL_?, offsets in m/s^2\n";
  const std::string source = "AP_InertialSensor.cpp";
  for (int k = 0; k < 3; ++k) {
    const std::string name = p + "OFFS_" + kAxes[k];
    check_range(in, out, name, t.offset(k), -3.5, 3.5, source);
    w.param(name, t.offset(k));
  }
  for (int k = 0; k < 3; ++k) {
    const std::string name = p + "SCAL_" + kAxes[k];
    check_range(in, out, name, t.matrix(k, k), 0.8, 1.2, source);
    w.param(name, t.matrix(k, k));
  }
}

void write_mag(const ExportInput& in, ExportOutput& out, Writer& w) {
  check_instance(in, "ardupilot", 3);
  const TargetCorrection t = in_target_units(in, *parse_unit("mG"), "ardupilot");
  const Mat3 S = symmetric_form(in, out, "ardupilot", t.matrix);
  const std::string n = in.instance == 0 ? "" : std::to_string(in.instance + 1);
  w.text += "# corrected = M (v + COMPASS_OFS" + n + "_?), M symmetric: diagonal COMPASS_DIA" + n + "_?, COMPASS_ODI" +
            n + "_X = M01, _Y = M02, _Z = M12; offsets in milligauss\n";
  for (int k = 0; k < 3; ++k) {
    const std::string name = "COMPASS_OFS" + n + "_" + kAxes[k];
    check_range(in, out, name, -t.offset(k), -400, 400, "AP_Compass.cpp");
    w.param(name, -t.offset(k));
  }
  const std::string fit = "CompassCalibrator::fit_acceptable";
  for (int k = 0; k < 3; ++k) {
    const std::string name = "COMPASS_DIA" + n + "_" + kAxes[k];
    check_range(in, out, name, S(k, k), 0.2, 5.0, fit);
    w.param(name, S(k, k));
  }
  const double odi[3] = {S(0, 1), S(0, 2), S(1, 2)};
  for (int k = 0; k < 3; ++k) {
    const std::string name = "COMPASS_ODI" + n + "_" + kAxes[k];
    check_range(in, out, name, odi[k], -1, 1, fit);
    w.param(name, odi[k]);
  }
}

void write_gyro(const ExportInput& in, ExportOutput& out, Writer& w) {
  check_instance(in, "ardupilot", 5);
  const TargetCorrection t = in_target_units(in, *parse_unit("rad/s"), "ardupilot");
  check_dropped(in, out, "ardupilot", "a gyroscope's scale factors and misalignment (ArduPilot stores offsets only)",
                dropped_share(t.matrix, Mat3::Identity()), false);
  const std::string p = ins_prefix(in.instance, "GYR");
  w.text += "# corrected = v - " + p + "OFFS_?, in rad/s\n";
  for (int k = 0; k < 3; ++k) w.param(p + "OFFS_" + kAxes[k], t.offset(k));
}

// INS_TCAL1_ .. INS_TCAL3_, then INS4_TCAL_, INS5_TCAL_; INS_ACC1_CALTEMP .. INS_ACC3_CALTEMP, INS4_ACC_CALTEMP.
std::string tcal_prefix(int instance) {
  return instance < 3 ? "INS_TCAL" + std::to_string(instance + 1) + "_"
                      : "INS" + std::to_string(instance + 1) + "_TCAL_";
}
std::string caltemp_name(int instance) {
  return instance < 3 ? "INS_ACC" + std::to_string(instance + 1) + "_CALTEMP"
                      : "INS" + std::to_string(instance + 1) + "_ACC_CALTEMP";
}

// The firmware subtracts P(T' - 35) - P(Tc' - 35) + OFFS, P without its constant term, T' and Tc' clamped to
// TMIN..TMAX: with CALTEMP Tc = 35 held to the range and OFFS = d_0 + P(Tc - 35) that is the fit's offset o(T').
void write_thermal(const ExportInput& in, ExportOutput& out, Writer& w) {
  check_instance(in, "ardupilot", 5);
  constexpr double kReference = 35;  // TEMP_REFERENCE, fixed in the firmware
  const double caltemp = std::clamp(kReference, in.thermal->range.low, in.thermal->range.high);
  const ThermalTarget t = thermal_in_target_units(in, out, *parse_unit("m/s^2"), "ardupilot", kReference, caltemp, 3);
  const std::string p = ins_prefix(in.instance, "ACC"), tc = tcal_prefix(in.instance);
  const double x = caltemp - kReference;
  w.text += "# thermal calibration " + in.thermal->model.name() + " over " + in.thermal->range.text() +
            " degC: corrected = (v - P(clamp(T) - 35) + P(clamp(" + caltemp_name(in.instance) + ") - 35) - " + p +
            "OFFS_?) .* " + p + "SCAL_?, P = 1e-6 (" + tc + "ACC1_? x + " + tc + "ACC2_? x^2 + " + tc +
            "ACC3_? x^3); offsets in m/s^2; " + tc + "ENABLE takes effect after a reboot\n";
  const std::string source = "AP_InertialSensor_tempcal.cpp";
  w.param(tc + "ENABLE", 1);
  check_range(in, out, tc + "TMIN", t.low, -70, 80, source);
  w.param(tc + "TMIN", t.low);
  check_range(in, out, tc + "TMAX", t.high, -70, 80, source);
  w.param(tc + "TMAX", t.high);
  for (int j = 1; j <= 3; ++j)
    for (int k = 0; k < 3; ++k) w.param(tc + "ACC" + std::to_string(j) + "_" + kAxes[k], 1e6 * t.polynomial(k, j));
  w.param(caltemp_name(in.instance), caltemp);
  for (int k = 0; k < 3; ++k) {
    const double offset =
        t.polynomial(k, 0) + ((t.polynomial(k, 3) * x + t.polynomial(k, 2)) * x + t.polynomial(k, 1)) * x;
    const std::string name = p + "OFFS_" + kAxes[k];
    check_range(in, out, name, offset, -3.5, 3.5, "AP_InertialSensor.cpp");
    w.param(name, offset);
  }
  for (int k = 0; k < 3; ++k) {
    const std::string name = p + "SCAL_" + kAxes[k];
    check_range(in, out, name, t.at_reference.matrix(k, k), 0.8, 1.2, "AP_InertialSensor.cpp");
    w.param(name, t.at_reference.matrix(k, k));
  }
}

void write(const ExportInput& in, ExportOutput& out) {
  Writer w{in, out,
           "# scalcal export --format ardupilot --instrument " + std::string(instrument_name(in.instrument)) +
               " (parameter file NAME,VALUE)\n"};
  if (in.thermal)
    write_thermal(in, out, w);
  else if (in.instrument == Instrument::accel)
    write_accel(in, out, w);
  else if (in.instrument == Instrument::mag)
    write_mag(in, out, w);
  else
    write_gyro(in, out, w);
  out.text = w.text;
}

}  // namespace

ExportFormat ardupilot_format() {
  return {"ardupilot",
          "ArduPilot's INS_ACC*, COMPASS_* and INS_GYR* parameters (m/s^2, milligauss, rad/s)",
          {Instrument::accel, Instrument::mag, Instrument::gyro},
          write,
          true};
}

}  // namespace scalcal
