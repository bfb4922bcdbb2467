// The imu_tk target: CalibratedTriad::load's text, X' = T K (X - B) with T of unit diagonal and K
// diagonal: K = diag(C), T = C K^-1, B = o (the log's raw units in, physical units out).
#include "numeric/export/formats.hpp"
#include "numeric/export/target_units.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal {
namespace {

void write(const ExportInput& in, ExportOutput& out) {
  const Mat3& C = in.correction.matrix;
  const Vec3 K = C.diagonal();
  for (int i = 0; i < 3; ++i)
    if (!(K(i) != 0))
      throw InputError(in.file, 0,
                       "its matrix has a zero diagonal entry (row " + std::to_string(i + 1) +
                           "): IMU-TK's form T K with T of unit diagonal cannot hold it (axes permuted?)");
  // Divided, not multiplied by 1 / K: x / x is exactly 1, as IMU-TK's unit diagonal is.
  Mat3 T;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T(i, j) = C(i, j) / K(j);
  // CalibratedTriad::load reads 9 + 9 + 3 numbers, row by row, and nothing else (no comments).
  std::string s;
  for (int i = 0; i < 3; ++i) s += exact_text(T(i, 0)) + " " + exact_text(T(i, 1)) + " " + exact_text(T(i, 2)) + "\n";
  s += "\n";
  for (int i = 0; i < 3; ++i)
    s += exact_text(i == 0 ? K(0) : 0) + " " + exact_text(i == 1 ? K(1) : 0) + " " + exact_text(i == 2 ? K(2) : 0) +
         "\n";
  s += "\n";
  for (int i = 0; i < 3; ++i) s += exact_text(in.correction.offset(i)) + "\n";
  out.text = s;
}

}  // namespace

ExportFormat imu_tk_format() {
  return {"imu_tk",
          "IMU-TK's CalibratedTriad text: X' = T K (X - B)",
          {Instrument::accel, Instrument::mag, Instrument::gyro},
          write,
          false};
}

}  // namespace scalcal
