// The px4 target: a QGroundControl parameter file. Accelerometer (m/s^2): corrected = (v - OFF) .*
// SCALE (Accelerometer::Correct), so OFF = offset, SCALE = diag(C) and the off-diagonal terms are
// dropped. Magnetometer (gauss): corrected = S (v - OFF) with S symmetric (Magnetometer::Correct):
// S = the symmetric factor of C = Q S, diagonal SCALE, ODIAG (S01, S02, S12); Q is dropped.
// Gyroscope (rad/s): OFF only. Four instances of each (CAL_ACC0 .. CAL_ACC3). Ranges from PX4's
// parameter metadata: SCALE 0.1 .. 3.0. A thermal fit (BASE+Tk, k <= 3) adds the accelerometer's
// TC_A{n} offset polynomial about TREF (TemperatureCompensation::calc_thermal_offsets_3D, subtracted before
// CAL_ACC{n}_?OFF by Accelerometer::Correct; docs/thermal_export_sources.md).
#include "numeric/export/formats.hpp"
#include "numeric/export/matrix_forms.hpp"
#include "numeric/export/target_units.hpp"
#include "numeric/export/thermal_offsets.hpp"

namespace scalcal {
namespace {

const char* const kAxes[3] = {"X", "Y", "Z"};

struct Writer {
  const ExportInput& in;
  ExportOutput& out;
  std::string text;
  void param(const std::string& name, double v) {
    check_float32(in, name, v);
    text += "1\t1\t" + name + "\t" + float_text(v) + "\t9\n";
    out.parameters.push_back({name, v});
  }
  void integer(const std::string& name, int v) {  // MAV_PARAM_TYPE_INT32
    text += "1\t1\t" + name + "\t" + std::to_string(v) + "\t6\n";
    out.parameters.push_back({name, static_cast<double>(v)});
  }
};

// TREF the fitted range's middle, TMIN..TMAX the range; X0 = 0 and the constant in CAL_ACC{n}_?OFF, as
// PX4's own accelerometer thermal calibration leaves them (temperature_calibration/accel.cpp).
void write_thermal(const ExportInput& in, ExportOutput& out) {
  check_instance(in, "px4", 4);
  const std::string n = std::to_string(in.instance), tc = "TC_A" + n + "_";
  const double reference = in.thermal->range.middle();
  const ThermalTarget t = thermal_in_target_units(in, out, *parse_unit("m/s^2"), "px4", reference, reference, 3);
  Writer w{in, out,
           "# scalcal export --format px4 --instrument accel (QGroundControl parameter file; thermal calibration " +
               in.thermal->model.name() + " over " + in.thermal->range.text() + " degC, offsets in m/s^2)\n"};
  w.text += "# corrected = (v - P(clamp(T, " + tc + "TMIN, " + tc + "TMAX) - " + tc + "TREF) - CAL_ACC" + n +
            "_?OFF) .* CAL_ACC" + n + "_?SCALE, P = " + tc + "X0_? + " + tc + "X1_? dT + " + tc + "X2_? dT^2 + " + tc +
            "X3_? dT^3\n# set " + tc + "ID and CAL_ACC" + n +
            "_ID to the sensor's device id on the vehicle; TC_A_ENABLE takes effect after a reboot\n"
            "# Vehicle-Id\tComponent-Id\tName\tValue\tType\n";
  w.integer("TC_A_ENABLE", 1);
  w.param(tc + "TREF", reference);
  w.param(tc + "TMIN", t.low);
  w.param(tc + "TMAX", t.high);
  for (int j = 0; j <= 3; ++j)
    for (int k = 0; k < 3; ++k)
      w.param(tc + "X" + std::to_string(j) + "_" + std::to_string(k), j == 0 ? 0.0 : t.polynomial(k, j));
  for (int k = 0; k < 3; ++k) w.param("CAL_ACC" + n + "_" + kAxes[k] + "OFF", t.at_reference.offset(k));
  for (int k = 0; k < 3; ++k) {
    const std::string name = "CAL_ACC" + n + "_" + kAxes[k] + "SCALE";
    check_range(in, out, name, t.at_reference.matrix(k, k), 0.1, 3.0, "PX4 parameter metadata");
    w.param(name, t.at_reference.matrix(k, k));
  }
  out.text = w.text;
}

void write(const ExportInput& in, ExportOutput& out) {
  if (in.thermal) return write_thermal(in, out);
  check_instance(in, "px4", 4);
  const std::string n = std::to_string(in.instance);
  const char* unit = in.instrument == Instrument::accel ? "m/s^2"
                     : in.instrument == Instrument::mag ? "gauss"
                                                        : "rad/s";
  const TargetCorrection t = in_target_units(in, *parse_unit(unit), "px4");
  Writer w{in, out,
           "# scalcal export --format px4 --instrument " + std::string(instrument_name(in.instrument)) +
               " (QGroundControl parameter file; offsets in " + unit + ")\n"};
  const std::string metadata = "PX4 parameter metadata";
  if (in.instrument == Instrument::accel) {
    const Mat3 D = t.matrix.diagonal().asDiagonal();
    check_dropped(in, out, "px4", "an accelerometer's non-orthogonality (off-diagonal terms)",
                  dropped_share(t.matrix, D));
    w.text += "# corrected = (v - CAL_ACC" + n + "_?OFF) .* CAL_ACC" + n + "_?SCALE; set CAL_ACC" + n +
              "_ID to the sensor's device id on the vehicle\n# Vehicle-Id\tComponent-Id\tName\tValue\tType\n";
    for (int k = 0; k < 3; ++k) w.param("CAL_ACC" + n + "_" + kAxes[k] + "OFF", t.offset(k));
    for (int k = 0; k < 3; ++k) {
      const std::string name = "CAL_ACC" + n + "_" + kAxes[k] + "SCALE";
      check_range(in, out, name, t.matrix(k, k), 0.1, 3.0, metadata);
      w.param(name, t.matrix(k, k));
    }
  } else if (in.instrument == Instrument::mag) {
    const Mat3 S = symmetric_form(in, out, "px4", t.matrix);
    w.text += "# corrected = S (v - CAL_MAG" + n + "_?OFF), S symmetric: diagonal CAL_MAG" + n + "_?SCALE, CAL_MAG" +
              n + "_ODIAG X = S01, Y = S02, Z = S12\n# Vehicle-Id\tComponent-Id\tName\tValue\tType\n";
    for (int k = 0; k < 3; ++k) w.param("CAL_MAG" + n + "_" + kAxes[k] + "OFF", t.offset(k));
    for (int k = 0; k < 3; ++k) {
      const std::string name = "CAL_MAG" + n + "_" + kAxes[k] + "SCALE";
      check_range(in, out, name, S(k, k), 0.1, 3.0, metadata);
      w.param(name, S(k, k));
    }
    w.param("CAL_MAG" + n + "_XODIAG", S(0, 1));
    w.param("CAL_MAG" + n + "_YODIAG", S(0, 2));
    w.param("CAL_MAG" + n + "_ZODIAG", S(1, 2));
  } else {
    check_dropped(in, out, "px4", "a gyroscope's scale factors and misalignment (PX4 stores offsets only)",
                  dropped_share(t.matrix, Mat3::Identity()), false);
    w.text += "# corrected = v - CAL_GYRO" + n + "_?OFF\n# Vehicle-Id\tComponent-Id\tName\tValue\tType\n";
    for (int k = 0; k < 3; ++k) w.param("CAL_GYRO" + n + "_" + kAxes[k] + "OFF", t.offset(k));
  }
  out.text = w.text;
}

}  // namespace

ExportFormat px4_format() {
  return {"px4",
          "PX4's CAL_ACCn / CAL_MAGn / CAL_GYROn parameters (QGroundControl file; m/s^2, gauss, rad/s)",
          {Instrument::accel, Instrument::mag, Instrument::gyro},
          write,
          true};
}

}  // namespace scalcal
