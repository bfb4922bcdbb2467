// The json target: scalcal's own convention, physical = matrix (raw - offset), with the
// calibration file's metadata (what it is of, its units, when and by what it was made).
#include "numeric/export/formats.hpp"
#include "numeric/export/target_units.hpp"

namespace scalcal {
namespace {

std::string triple(const Vec3& v) {
  return "[" + exact_text(v(0)) + ", " + exact_text(v(1)) + ", " + exact_text(v(2)) + "]";
}

void write(const ExportInput& in, ExportOutput& out) {
  const Mat3& C = in.correction.matrix;
  std::string s = "{\n";
  for (const auto& [key, text] : in.kept) s += "  \"" + key + "\": " + text + ",\n";
  s += "  \"convention\": \"physical = matrix (raw - offset), matrix by rows\",\n";
  s += "  \"offset\": " + triple(in.correction.offset) + ",\n";
  s += "  \"matrix\": [" + triple(C.row(0)) + ", " + triple(C.row(1)) + ", " + triple(C.row(2)) + "]\n}\n";
  out.text = s;
}

}  // namespace

ExportFormat json_format() {
  return {"json",
          "scalcal's own convention with the file's metadata and units",
          {Instrument::accel, Instrument::mag, Instrument::gyro},
          write,
          false};
}

}  // namespace scalcal
