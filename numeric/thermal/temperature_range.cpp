// Parsing and printing of a temperature range (temperature_range.hpp).
#include "numeric/thermal/temperature_range.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace scalcal {
namespace {

double celsius_number(const std::string& s, const std::string& whole) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v))
    throw std::invalid_argument("'" + whole + "' is not T1..T2 in degrees Celsius ('" + s + "' is not a number)");
  if (v < -273.15 || v > 1000)
    throw std::invalid_argument("'" + whole + "': " + s + " degrees Celsius is outside -273.15..1000");
  return v;
}

// Fixed-point with the fewest decimals that read back to v (temperatures: no exponent).
std::string shortest(double v) {
  char buffer[64];
  for (int decimals = 0; decimals <= 12; ++decimals) {
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    if (std::strtod(buffer, nullptr) == v) return buffer;
  }
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

}  // namespace

std::string TemperatureRange::text() const { return shortest(low) + ".." + shortest(high); }

TemperatureRange parse_temperature_range(const std::string& text) {
  const auto dots = text.find("..");
  if (dots == std::string::npos)
    throw std::invalid_argument("'" + text + "' is not T1..T2 in degrees Celsius (for example -20..60)");
  TemperatureRange r{celsius_number(text.substr(0, dots), text), celsius_number(text.substr(dots + 2), text)};
  if (!(r.low < r.high))
    throw std::invalid_argument("'" + text +
                                "': the range needs T1 < T2 (a thermal model needs two temperatures or more)");
  return r;
}

}  // namespace scalcal
