// The c target: a C header for firmware (embedded/README.md, "The header of scalcal export --format
// c"): the correction and what the calibration file states of it as macros, and one static inline
// function applying it, physical = MATRIX (raw - OFFSET); the embedded library takes the same
// numbers (scalcal_calibration_from_matrix). The log's raw units in, the calibration's physical
// units out, as scalcal's own correction: nothing converted, the units stated.
#include <cctype>
#include <cmath>

#include "numeric/export/formats.hpp"
#include "numeric/export/target_units.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal {
namespace {

std::string triple(const Vec3& v) {
  return "{" + exact_text(v(0)) + ", " + exact_text(v(1)) + ", " + exact_text(v(2)) + "}";
}

// A standard error, -1 where the model has none or the fit could not estimate it.
std::string std_triple(const Vec3& v) {
  Vec3 w = v;
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(w(i))) w(i) = -1;
  return triple(w);
}

// A parameter the model does not have is 0.
Vec3 or_zero(const Vec3& v) {
  Vec3 w = v;
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(w(i))) w(i) = 0;
  return w;
}

// A C string literal of a label: printable ASCII only, quotes and backslashes escaped.
std::string literal(const std::string& s) {
  std::string out = "\"";
  for (const unsigned char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
  }
  return out + "\"";
}

// A label inside a /* */ comment: no "*/", printable ASCII.
std::string commented(const std::string& s) {
  std::string out;
  for (const unsigned char c : s) out += (c >= 32 && c < 127) ? static_cast<char>(c) : '?';
  for (auto at = out.find("*/"); at != std::string::npos; at = out.find("*/")) out.replace(at, 2, "* /");
  return out;
}

std::string unit_label(const std::optional<Unit>& u, bool counts) {
  return u ? std::string(u->name) : counts ? "counts" : "";
}

void write(const ExportInput& in, ExportOutput& out) {
  std::string prefix = in.name.empty() ? "CAL" : in.name;
  if (!std::isalpha(static_cast<unsigned char>(prefix[0])))
    throw RequestError("name", "must be a C identifier (a letter, then letters, digits or _), got '" + prefix + "'");
  for (char& c : prefix) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_')
      throw RequestError("name", "must be a C identifier (a letter, then letters, digits or _), got '" + in.name + "'");
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  std::string lower = prefix;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const CalibrationFacts& f = in.facts;
  const std::string P = "SCALCAL_" + prefix + "_";
  const Mat3& C = in.correction.matrix;
  // The C library's model is its count of parameters (scalcal_model: 3, 6 or 9); a file naming no model is the paper's.
  const std::optional<ModelKind> kind = parse_model(f.model);
  const int parameters = kind ? model_parameters(*kind) : model_parameters(ModelKind::paper9);
  std::string s = "/* scalcal calibration: `scalcal export --format c` (" + commented(f.tool) +
                  "). Sensor: " + commented(f.sensor) + ".\n * physical = " + P + "MATRIX (raw - " + P +
                  "OFFSET), the paper's convention (phi_kj = phi_jk). */\n";
  s += "#ifndef SCALCAL_" + prefix + "_H\n#define SCALCAL_" + prefix + "_H\n";
  const auto define = [&](const std::string& name, const std::string& value, const std::string& comment = "") {
    s += "#define " + P + name + " " + value + (comment.empty() ? "" : "  /* " + comment + " */") + "\n";
  };
  define("FORMAT", "1", "this layout's version");
  define("MODEL", std::to_string(parameters), "parameters: 3 bias3, 6 axis6, 9 paper9");
  define("MODEL_NAME", literal(f.model));
  define("INSTRUMENT", literal(std::string(instrument_name(in.instrument))), "accel, mag or gyro");
  define("SENSOR", literal(f.sensor));
  define("UNITS_RAW", literal(unit_label(in.units.raw, in.units.raw_counts)), "\"\" when not said");
  define("UNITS_PHYSICAL",
         literal(in.units.unit_modulus ? std::string("unit modulus") : unit_label(in.units.physical, false)));
  define("MAGNITUDE", exact_text(in.units.unit_modulus ? 1.0 : f.magnitude), "|I| in physical units");
  define("MAGNITUDE_AUTO", in.units.unit_modulus ? "1" : "0", "1: the field's strength was unknown (unit modulus)");
  define("NOMINAL_GAIN", exact_text(f.nominal_gain), "raw units per physical unit");
  define("OFFSET", triple(in.correction.offset), "raw units");
  define("MATRIX", "{" + triple(C.row(0)) + ", " + triple(C.row(1)) + ", " + triple(C.row(2)) + "}",
         "physical per raw unit, by rows");
  define("SCALE_DEVIATION", triple(or_zero(f.scale_deviation)), "relative to the nominal gain");
  define("NONORTHOGONALITY", triple(or_zero(f.nonorthogonality)), "gamma_xy, gamma_yz, gamma_zx, rad");
  define("BIAS_STD", std_triple(f.bias_std), "raw units; -1: not estimable");
  define("SCALE_DEVIATION_STD", std_triple(f.scale_deviation_std));
  define("NONORTHOGONALITY_STD", std_triple(f.nonorthogonality_std), "rad");
  define("RESIDUAL_RMS", exact_text(f.residual_rms), "physical units");
  define("POSITIONS", std::to_string(f.positions));
  define("SAMPLES", std::to_string(f.samples));
  s += "static inline void scalcal_" + lower +
       "_apply(const float raw[3], float physical[3]) {\n"
       "  static const float o[3] = " +
       P + "OFFSET, m[3][3] = " + P +
       "MATRIX;\n"
       "  const float d[3] = {raw[0] - o[0], raw[1] - o[1], raw[2] - o[2]};\n"
       "  int i;\n"
       "  for (i = 0; i < 3; ++i) physical[i] = m[i][0] * d[0] + m[i][1] * d[1] + m[i][2] * d[2];\n"
       "}\n#endif\n";
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) check_float32(in, "the matrix", C(i, j));
  for (int i = 0; i < 3; ++i) check_float32(in, "the offset", in.correction.offset(i));
  out.text = s;
}

}  // namespace

ExportFormat c_format() {
  return {"c",
          "a C header for firmware: the correction as macros and scalcal_cal_apply() (embedded/)",
          {Instrument::accel, Instrument::mag, Instrument::gyro},
          write,
          false};
}

}  // namespace scalcal
