// calibrate --instrument gyro's options as a GyroCalibrateRequest (calibrate_gyro.hpp): the log's
// options are the accelerometer's; --magnitude, --turn-angle or --accelerometer name the method.
#include <cmath>
#include <cstdlib>
#include <string>

#include "commands/calibration/calibrate.hpp"
#include "commands/calibration/calibrate_gyro.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {

namespace {

// "E,N,U": three finite numbers, not all zero, normalised.
Vec3 table_axis(const std::string& text) {
  Vec3 a;
  std::size_t at = 0;
  for (int k = 0; k < 3; ++k) {
    const std::size_t end = k < 2 ? text.find(',', at) : text.size();
    const std::string part = end == std::string::npos ? "" : text.substr(at, end - at);
    char* stop = nullptr;
    a(k) = part.empty() ? NAN : std::strtod(part.c_str(), &stop);
    if (part.empty() || *stop != '\0' || !std::isfinite(a(k)))
      throw UsageError(words("{table-axis}: expected E,N,U (three numbers, east, north, up), got '") + text + "'");
    at = end + 1;
  }
  if (!(a.norm() > 0) || !std::isfinite(a.norm()))
    throw UsageError(words("{table-axis}: the axis ") + text + " has no direction (all zero)");
  return a.normalized();
}

// --magnitude RATE|auto|column:NAME.
TableRate table_rate(const std::string& text) {
  TableRate out;
  if (text.rfind("column:", 0) == 0) {
    out.column = text.substr(7);
    if (out.column.empty()) throw UsageError(words("calibrate: {magnitude column:NAME} needs the column's name"));
    return out;
  }
  out.rate = magnitude_value(text);  // a positive number or auto: the option's why_bad saw to it
  return out;
}

}  // namespace

GyroCalibrateRequest gyro_calibrate_request(const Values& v) {
  GyroCalibrateRequest q;
  q.file = v.text("--measurements");
  read_log_options(v, q.format, q.rate, q.intervals);
  if (v.given("--magnitude")) q.magnitude = table_rate(v.text("--magnitude"));
  if (v.given("--turn-angle")) q.turn_angle_deg = v.number("--turn-angle");
  q.accelerometer = v.text("--accelerometer");
  if (v.given("--accelerometer-magnitude"))
    q.accelerometer_magnitude = magnitude_value(v.text("--accelerometer-magnitude"));
  if (v.given("--latitude")) q.latitude_deg = v.number("--latitude");
  if (v.given("--table-axis")) {
    if (!q.latitude_deg)
      throw UsageError(words("calibrate: {table-axis} places the Earth's rate: it needs {latitude}"));
    q.table_axis = table_axis(v.text("--table-axis"));
  }
  // Options of an accelerometer's calibration that a gyro's does not take.
  for (const char* o :
       {"--modulus", "--weights", "--keep-outliers", "--suggest", "--criterion", "--region", "--program"})
    if (v.given(o)) throw UsageError(words("calibrate {instrument gyro}: ") + o + " is an accelerometer's option");
  q.sensor = v.text("--sensor");
  q.physical_units = "";
  if (const std::string units = v.text("--units"); !units.empty()) {
    const auto comma = units.find(',');
    if (comma == std::string::npos || comma == 0 || comma + 1 == units.size())
      throw UsageError(words("{units}: expected RAW,PHYSICAL (for example counts,rad/s), got '") + units + "'");
    q.raw_units = units.substr(0, comma);
    q.physical_units = units.substr(comma + 1);
  }
  if (v.given("--temperature"))
    throw UsageError(words("{temperature} belongs to a thermal model, not to {instrument gyro}"));
  if (v.text("--model") != "auto") {
    const auto model = parse_model(v.text("--model"));
    if (!model)
      throw UsageError(words("{instrument gyro}: {model} ") + v.text("--model") +
                       " is no gyro model (thermal models are the accelerometer's and magnetometer's)");
    if (!model_supports(*model, ModelCapability::auto_choice))
      throw UsageError(words("{instrument gyro}: {model} ") + v.text("--model") + ": a gyro is calibrated under " +
                       models_supporting(ModelCapability::auto_choice) + " (offsets, gains and non-orthogonality)");
    q.model = *model;
  }
  gyro_method(q);  // refuses a contradictory set of options before any file is read
  return q;
}

}  // namespace scalcal::commands
