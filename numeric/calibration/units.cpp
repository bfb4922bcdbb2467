// The unit table and the Earth's magnitudes (units.hpp).
#include "numeric/calibration/units.hpp"

#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>

namespace scalcal {
namespace {

struct Spelling {
  std::string_view alias;
  Unit unit;
};

constexpr double kStandardGravity = 9.80665;  // m/s^2 (CGPM 1901)
constexpr double kPi = 3.14159265358979323846;

constexpr Unit kMps2{"m/s^2", Quantity::acceleration, 1};
constexpr Unit kG{"g", Quantity::acceleration, kStandardGravity};
constexpr Unit kMilliG{"mg", Quantity::acceleration, kStandardGravity / 1000};
constexpr Unit kGauss{"gauss", Quantity::magnetic_field, 1};
constexpr Unit kMilliGauss{"mG", Quantity::magnetic_field, 1e-3};
constexpr Unit kTesla{"T", Quantity::magnetic_field, 1e4};
constexpr Unit kMilliTesla{"mT", Quantity::magnetic_field, 10};
constexpr Unit kMicroTesla{"uT", Quantity::magnetic_field, 1e-2};
constexpr Unit kNanoTesla{"nT", Quantity::magnetic_field, 1e-5};
constexpr Unit kRadPerS{"rad/s", Quantity::angular_rate, 1};
constexpr Unit kDegPerS{"deg/s", Quantity::angular_rate, kPi / 180};

constexpr std::array<Spelling, 27> kSpellings{{
    {"m/s^2", kMps2},
    {"m/s2", kMps2},
    {"m/s/s", kMps2},
    {"m s^-2", kMps2},
    {"g", kG},
    {"g0", kG},
    {"mg", kMilliG},
    {"milli-g", kMilliG},
    {"gauss", kGauss},
    {"Gs", kGauss},
    {"Ga", kGauss},
    {"mG", kMilliGauss},
    {"mGauss", kMilliGauss},
    {"milligauss", kMilliGauss},
    {"T", kTesla},
    {"mT", kMilliTesla},
    {"uT", kMicroTesla},
    {"\xC2\xB5T", kMicroTesla},
    {"microtesla", kMicroTesla},
    {"nT", kNanoTesla},
    {"rad/s", kRadPerS},
    {"rad s^-1", kRadPerS},
    {"deg/s", kDegPerS},
    {"dps", kDegPerS},
    {"\xC2\xB0/s", kDegPerS},
    {"degrees/s", kDegPerS},
    {"tesla", kTesla},
}};

struct EarthRange {
  Instrument instrument;
  Unit unit;
  double low, high;
};

// Gravity on the Earth's surface: 9.7639 (Huascaran) to 9.8337 (Arctic Ocean) m/s^2; the
// geomagnetic field's total intensity: about 22 (South Atlantic anomaly) to 67 uT (near the poles).
constexpr std::array<EarthRange, 7> kEarth{{
    {Instrument::accel, kMps2, 9.76, 9.84},
    {Instrument::accel, kG, 0.995, 1.005},
    {Instrument::accel, kMilliG, 995, 1005},
    {Instrument::mag, kMicroTesla, 22, 67},
    {Instrument::mag, kGauss, 0.22, 0.67},
    {Instrument::mag, kMilliGauss, 220, 670},
    {Instrument::mag, kNanoTesla, 22000, 67000},
}};

}  // namespace

std::optional<Unit> parse_unit(std::string_view name) {
  for (const auto& s : kSpellings)
    if (s.alias == name) return s.unit;
  return std::nullopt;
}

bool is_count_unit(std::string_view name) {
  return name == "counts" || name == "count" || name == "LSB" || name == "lsb" || name == "adc";
}

std::string unit_names() {
  return "m/s^2, g, mg (acceleration); gauss, mG, T, mT, uT, nT (magnetic field); rad/s, deg/s (rate); counts "
         "(raw only)";
}

std::string_view quantity_name(Quantity q) {
  return q == Quantity::acceleration ? "acceleration" : q == Quantity::magnetic_field ? "magnetic field" : "rate";
}

std::optional<Unit> unit_of_earth_magnitude(Instrument instrument, double magnitude) {
  for (const auto& e : kEarth)
    if (e.instrument == instrument && magnitude >= e.low && magnitude <= e.high) return e.unit;
  return std::nullopt;
}

std::optional<Amount> parse_amount(std::string_view text) {
  const std::string s(text);
  const char* begin = s.c_str();
  char* end = nullptr;
  double value = std::strtod(begin, &end);
  if (end == begin) return std::nullopt;
  if (*end == '/') {  // 1/16384 g: a ratio, as datasheets give an LSB
    const char* d = end + 1;
    char* e2 = nullptr;
    const double denominator = std::strtod(d, &e2);
    if (e2 == d || !(denominator > 0)) return std::nullopt;
    value /= denominator;
    end = e2;
  }
  while (*end == ' ') ++end;
  const auto unit = parse_unit(end);
  if (!unit || !std::isfinite(value) || !(value > 0)) return std::nullopt;
  return Amount{value, *unit};
}

}  // namespace scalcal
