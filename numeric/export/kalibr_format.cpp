// The kalibr target: the `imu0:` block that Kalibr's and OpenVINS's IMU readers load, in SI units
// (m/s^2, rad/s). Kalibr's scale-misalignment model measures raw = M a + b with M lower triangular
// in the accelerometer's frame (IccSensors.py, `accelerometers: M:`); OpenVINS (model "kalibr",
// VioManagerOptions.h, Propagator.cpp) reads Ta = M and corrects a = R_ACCtoIMU Da (a_m - b_a),
// Da = Ta^-1 lower triangular, R_ACCtoIMU = R_IMUtoACC^T. scalcal's C (in SI) = Q L with Q a
// rotation and L lower triangular gives Ta = L^-1 and R_IMUtoACC = Q^T; the gyroscope's block the
// same way from a gyro calibration (Tw, R_IMUtoGYRO, `gyroscopes: M:`, `C_gyro_i:`). Both tools
// estimate the biases online and have no key for them: the offset is stated in a comment only.
#include <cmath>
#include <cstdio>

#include "numeric/export/formats.hpp"
#include "numeric/export/matrix_forms.hpp"
#include "numeric/export/target_units.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal {
namespace {

std::string row_text(const Mat3& m, int i) {
  return "[" + exact_text(m(i, 0)) + ", " + exact_text(m(i, 1)) + ", " + exact_text(m(i, 2)) + "]";
}

std::string block(const std::string& indent, const std::string& key, const Mat3& m) {
  std::string s = indent + key + ":\n";
  for (int i = 0; i < 3; ++i) s += indent + "  - " + row_text(m, i) + "\n";
  return s;
}

void write(const ExportInput& in, ExportOutput& out) {
  const bool gyro = in.instrument == Instrument::gyro;
  const Unit si = *parse_unit(gyro ? "rad/s" : "m/s^2");
  const TargetCorrection t = in_target_units(in, si, "kalibr");
  const auto f = rotation_times_lower(t.matrix);
  if (!f)
    throw InputError(in.file, 0,
                     "its matrix has a negative determinant (left-handed sensor axes: an axis' sign or two axes "
                     "swapped in the log); Kalibr's and OpenVINS's rotation and triangle cannot hold a reflection");
  out.rotation_rad = rotation_angle(f->rotation);
  const Mat3 T = f->lower.inverse();  // Ta or Tw: raw = T a + b
  const Mat3 R_imu_to = f->rotation.transpose();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      check_float32(in, gyro ? "Tw" : "Ta", T(i, j));
      check_float32(in, "R_IMUto", R_imu_to(i, j));
    }
  const Mat3 I = Mat3::Identity();
  std::string s =
      "# scalcal export --format kalibr: the imu0 block of Kalibr's imu.yaml (scale-misalignment model) and\n"
      "# OpenVINS's kalibr_imu_chain.yaml (model kalibr), SI units: merge it with the noise keys of your own\n"
      "# (accelerometer_/gyroscope_noise_density, _random_walk). The biases are estimated online by both;\n";
  s += "# this calibration's offset, for their initial bias: [" + exact_text(t.offset(0)) + ", " +
       exact_text(t.offset(1)) + ", " + exact_text(t.offset(2)) + "] " + std::string(si.name) + ".\n";
  s += std::string("# The ") + (gyro ? "accelerometer" : "gyroscope") +
       "'s blocks are identity: this calibration is not of it.\n";
  s += "imu0:\n  model: kalibr\n  rostopic: /imu0\n  time_offset: 0.0\n";
  if (std::isfinite(in.sample_rate)) s += "  update_rate: " + float_text(in.sample_rate) + "\n";
  if (std::isfinite(in.noise) && std::isfinite(in.sample_rate)) {
    // White noise of one sample sigma at rate f is a density sigma / sqrt(f) per sqrt(Hz).
    const double density = in.noise * t.per_physical / std::sqrt(in.sample_rate);
    char d[32];
    std::snprintf(d, sizeof d, "%.4g", density);
    s += std::string("  # ") + (gyro ? "gyroscope" : "accelerometer") + "_noise_density: " + d +
         " (this log's white noise); both readers also need the noise densities and random walks (an Allan "
         "variance)\n";
  }
  s += block("  ", "Ta", gyro ? I : T) + block("  ", "R_IMUtoACC", gyro ? I : R_imu_to);
  s += block("  ", "Tw", gyro ? T : I) + block("  ", "R_IMUtoGYRO", gyro ? R_imu_to : I);
  s += block("  ", "Tg", Mat3::Zero());
  s += "  accelerometers:\n" + block("    ", "M", gyro ? I : T);
  s += "  gyroscopes:\n" + block("    ", "M", gyro ? T : I) + block("    ", "A", Mat3::Zero()) +
       block("    ", "C_gyro_i", gyro ? R_imu_to : I);
  out.text = s;
  out.warnings.push_back(std::string("the ") + (gyro ? "accelerometer" : "gyroscope") +
                         "'s blocks (Ta, R_IMUtoACC or Tw, R_IMUtoGYRO, Tg) are identity or zero: merge them with "
                         "that meter's calibration; Kalibr and OpenVINS estimate the biases online, the offset is "
                         "in a comment");
}

}  // namespace

ExportFormat kalibr_format() {
  return {"kalibr",
          "the imu0 block Kalibr's and OpenVINS's IMU readers load (SI units)",
          {Instrument::accel, Instrument::gyro},
          write,
          false};
}

}  // namespace scalcal
