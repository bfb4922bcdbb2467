// The targets of `scalcal export` (export.hpp), one function each: the text a tool loads, from
// physical = C (raw - o).
#include <cmath>
#include <cstdio>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include "commands/export.hpp"
#include "commands/export_formats.hpp"
#include "commands/usage_error.hpp"

namespace scalcal::commands {
namespace {

std::string digits(double v, int significant) {
  char s[40];
  std::snprintf(s, sizeof s, "%.*g", significant, v == 0 ? 0.0 : v);
  return s;
}
std::string exact(double v) { return digits(v, 17); }
std::string single(double v) { return digits(v, 9); }

// The angle of a rotation matrix (radians).
double rotation_angle(const Mat3& R) { return std::acos(std::clamp((R.trace() - 1) / 2, -1.0, 1.0)); }

const char* kAxes[3] = {"X", "Y", "Z"};

void require_accel(const ExportRequest& q, const char* format) {
  if (q.instrument != "accel")
    throw UsageError(std::string("--format ") + format + " has an accelerometer model only (--instrument accel)");
}

// The diagonal-only forms: the largest |C_off v| / |C v| over directions v (spectral norms).
double dropped_share(const Mat3& C) {
  Mat3 off = C;
  off.diagonal().setZero();
  const Eigen::JacobiSVD<Mat3> svd(C);
  return Eigen::JacobiSVD<Mat3>(off).singularValues()(0) / svd.singularValues()(2);
}

}  // namespace

Mat3 symmetric_factor(const Mat3& C) {
  const Eigen::SelfAdjointEigenSolver<Mat3> e(C.transpose() * C);
  return e.eigenvectors() * e.eigenvalues().cwiseSqrt().asDiagonal() * e.eigenvectors().transpose();
}

void write_magcal(const ExportRequest&, ExportResult& r) {
  const Mat3& C = r.correction.matrix;
  const Vec3& o = r.correction.offset;
  std::string s =
      "% scalcal export --format magcal: MATLAB magcal's convention for rows d of raw data,\n"
      "% corrected = (d - b) * A; A = matrix' and b = offset' of physical = matrix (raw - offset).\n"
      "A = [";
  for (int i = 0; i < 3; ++i)
    s += exact(C(0, i)) + " " + exact(C(1, i)) + " " + exact(C(2, i)) + (i < 2 ? "; " : "];\n");
  s += "b = [" + exact(o(0)) + " " + exact(o(1)) + " " + exact(o(2)) + "];\n";
  r.text = s;
}

void write_imu_tk(const ExportRequest&, ExportResult& r) {
  const Mat3& C = r.correction.matrix;
  const Vec3 K = C.diagonal();
  const Mat3 T = C * K.cwiseInverse().asDiagonal();
  // CalibratedTriad::load reads 9 + 9 + 3 numbers, row by row, and nothing else (no comments).
  std::string s;
  for (int i = 0; i < 3; ++i) s += exact(T(i, 0)) + " " + exact(T(i, 1)) + " " + exact(T(i, 2)) + "\n";
  s += "\n";
  for (int i = 0; i < 3; ++i)
    s += exact(i == 0 ? K(0) : 0) + " " + exact(i == 1 ? K(1) : 0) + " " + exact(i == 2 ? K(2) : 0) + "\n";
  s += "\n";
  for (int i = 0; i < 3; ++i) s += exact(r.correction.offset(i)) + "\n";
  r.text = s;
}

void write_kalibr(const ExportRequest& q, ExportResult& r) {
  require_accel(q, "kalibr");
  // C^-1 = M R: the QR decomposition of C^-T = Q1 R1 gives M = R1^T (lower) and R = Q1^T, signs
  // chosen so that M's diagonal is positive.
  const Mat3 A = r.correction.matrix.inverse();
  const Eigen::HouseholderQR<Mat3> qr(A.transpose());
  Mat3 M = Mat3(qr.matrixQR().triangularView<Eigen::Upper>()).transpose();
  Mat3 R = Mat3(qr.householderQ()).transpose();
  const Vec3 sign = M.diagonal().cwiseSign();
  M = M * sign.asDiagonal();
  R = sign.asDiagonal() * R;
  r.rotation_rad = rotation_angle(R);
  const auto row = [](const Mat3& m, int i) {
    return "[" + exact(m(i, 0)) + ", " + exact(m(i, 1)) + ", " + exact(m(i, 2)) + "]";
  };
  std::string s =
      "# scalcal export --format kalibr: kalibr's scale-misalignment accelerometer model,\n"
      "# raw = M a + b with M lower triangular. a = R physical, where physical = matrix (raw - offset)\n"
      "# is scalcal's correction and R a rotation (kalibr keeps it in the IMU's orientation).\n"
      "accelerometers:\n  model: scale-misalignment\n  M:\n";
  for (int i = 0; i < 3; ++i) s += "    - " + row(M, i) + "\n";
  s += "  b: [" + exact(r.correction.offset(0)) + ", " + exact(r.correction.offset(1)) + ", " +
       exact(r.correction.offset(2)) + "]\n  R:\n";
  for (int i = 0; i < 3; ++i) s += "    - " + row(R, i) + "\n";
  r.text = s;
}

void write_px4(const ExportRequest& q, ExportResult& r) {
  const Mat3& C = r.correction.matrix;
  const Vec3& o = r.correction.offset;
  const std::string n = std::to_string(q.instance);
  std::string s = "# scalcal export --format px4 --instrument " + q.instrument + " (QGroundControl parameter file)\n";
  const auto param = [&](const std::string& name, double v) { s += "1\t1\t" + name + "\t" + single(v) + "\t9\n"; };
  if (q.instrument == "accel") {
    r.dropped_relative = dropped_share(C);
    s += "# corrected = (raw - CAL_ACC" + n + "_?OFF) .* CAL_ACC" + n + "_?SCALE; set CAL_ACC" + n +
         "_ID to the sensor's device id on the vehicle\n# Vehicle-Id\tComponent-Id\tName\tValue\tType\n";
    for (int k = 0; k < 3; ++k) param("CAL_ACC" + n + "_" + kAxes[k] + "OFF", o(k));
    for (int k = 0; k < 3; ++k) param("CAL_ACC" + n + "_" + kAxes[k] + "SCALE", C(k, k));
  } else {
    const Mat3 S = symmetric_factor(C);
    r.rotation_rad = rotation_angle(C * S.inverse());
    s += "# corrected = S (raw - CAL_MAG" + n + "_?OFF), S symmetric: diagonal CAL_MAG" + n + "_?SCALE, CAL_MAG" + n +
         "_ODIAG X = S01, Y = S02, Z = S12\n# Vehicle-Id\tComponent-Id\tName\tValue\tType\n";
    for (int k = 0; k < 3; ++k) param("CAL_MAG" + n + "_" + kAxes[k] + "OFF", o(k));
    for (int k = 0; k < 3; ++k) param("CAL_MAG" + n + "_" + kAxes[k] + "SCALE", S(k, k));
    param("CAL_MAG" + n + "_XODIAG", S(0, 1));
    param("CAL_MAG" + n + "_YODIAG", S(0, 2));
    param("CAL_MAG" + n + "_ZODIAG", S(1, 2));
  }
  r.text = s;
}

void write_ardupilot(const ExportRequest& q, ExportResult& r) {
  const Mat3& C = r.correction.matrix;
  const Vec3& o = r.correction.offset;
  const std::string n = q.instance == 0 ? "" : std::to_string(q.instance + 1);
  std::string s = "# scalcal export --format ardupilot --instrument " + q.instrument + " (parameter file NAME,VALUE)\n";
  const auto param = [&](const std::string& name, double v) { s += name + "," + single(v) + "\n"; };
  if (q.instrument == "accel") {
    r.dropped_relative = dropped_share(C);
    s += "# corrected = (raw - INS_ACC" + n + "OFFS_?) .* INS_ACC" + n + "SCAL_?\n";
    for (int k = 0; k < 3; ++k) param("INS_ACC" + n + "OFFS_" + kAxes[k], o(k));
    for (int k = 0; k < 3; ++k) param("INS_ACC" + n + "SCAL_" + kAxes[k], C(k, k));
  } else {
    const Mat3 S = symmetric_factor(C);
    r.rotation_rad = rotation_angle(C * S.inverse());
    s += "# corrected = M (raw + COMPASS_OFS" + n + "_?), M symmetric: diagonal COMPASS_DIA" + n + "_?, COMPASS_ODI" +
         n + "_X = M01, _Y = M02, _Z = M12\n";
    for (int k = 0; k < 3; ++k) param("COMPASS_OFS" + n + "_" + kAxes[k], -o(k));
    for (int k = 0; k < 3; ++k) param("COMPASS_DIA" + n + "_" + kAxes[k], S(k, k));
    param("COMPASS_ODI" + n + "_X", S(0, 1));
    param("COMPASS_ODI" + n + "_Y", S(0, 2));
    param("COMPASS_ODI" + n + "_Z", S(1, 2));
  }
  r.text = s;
}

}  // namespace scalcal::commands
