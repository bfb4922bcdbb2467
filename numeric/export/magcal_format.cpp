// The magcal target: MATLAB magcal's convention for rows d of raw data, corrected = (d - b) A,
// so A = matrix' and b = offset' (in the log's raw units; the output in the calibration's physical
// units, as scalcal's).
#include "numeric/export/formats.hpp"
#include "numeric/export/target_units.hpp"

namespace scalcal {
namespace {

void write(const ExportInput& in, ExportOutput& out) {
  const Mat3& C = in.correction.matrix;
  const Vec3& o = in.correction.offset;
  std::string s =
      "% scalcal export --format magcal: MATLAB magcal's convention for rows d of raw data,\n"
      "% corrected = (d - b) * A; A = matrix' and b = offset' of physical = matrix (raw - offset).\n"
      "A = [";
  for (int i = 0; i < 3; ++i)
    s += exact_text(C(0, i)) + " " + exact_text(C(1, i)) + " " + exact_text(C(2, i)) + (i < 2 ? "; " : "];\n");
  s += "b = [" + exact_text(o(0)) + " " + exact_text(o(1)) + " " + exact_text(o(2)) + "];\n";
  out.text = s;
}

}  // namespace

ExportFormat magcal_format() {
  return {"magcal",
          "MATLAB magcal's A and b: corrected = (d - b) * A for rows d of raw data",
          {Instrument::accel, Instrument::mag, Instrument::gyro},
          write,
          false};
}

}  // namespace scalcal
