// calibrate --instrument gyro's options as a GyroCalibrateRequest (calibrate_gyro.hpp): the log's
// options are the accelerometer's; --magnitude, --turn-angle or --accelerometer name the method.
#include "commands/calibrate.hpp"
#include "commands/calibrate_gyro.hpp"
#include "commands/usage_error.hpp"

namespace scalcal::commands {

GyroCalibrateRequest gyro_calibrate_request(const Values& v) {
  GyroCalibrateRequest q;
  q.file = v.text("--measurements");
  read_log_options(v, q.format, q.rate, q.intervals);
  if (v.given("--magnitude")) q.magnitude = v.text("--magnitude");
  if (v.given("--turn-angle")) q.turn_angle_deg = v.number("--turn-angle");
  q.accelerometer = v.text("--accelerometer");
  if (v.given("--accelerometer-magnitude")) q.accelerometer_magnitude = v.text("--accelerometer-magnitude");
  if (v.given("--latitude")) q.latitude_deg = v.number("--latitude");
  // Options of an accelerometer's calibration that a gyro's does not take.
  for (const char* o :
       {"--modulus", "--weights", "--keep-outliers", "--suggest", "--criterion", "--region", "--program"})
    if (v.given(o))
      throw UsageError(std::string("calibrate --instrument gyro: ") + o + " is an accelerometer's option");
  q.sensor = v.text("--sensor");
  q.physical_units = "";
  if (const std::string units = v.text("--units"); !units.empty()) {
    const auto comma = units.find(',');
    if (comma == std::string::npos || comma == 0 || comma + 1 == units.size())
      throw UsageError("--units: expected RAW,PHYSICAL (for example counts,rad/s), got '" + units + "'");
    q.raw_units = units.substr(0, comma);
    q.physical_units = units.substr(comma + 1);
  }
  if (v.text("--model") != "auto") q.model = *parse_model(v.text("--model"));
  gyro_method(q);  // refuses a contradictory set of options before any file is read
  return q;
}

}  // namespace scalcal::commands
