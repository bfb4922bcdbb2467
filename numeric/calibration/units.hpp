// Units of a calibration: the raw units of the log (a physical unit, or ADC counts whose size the
// driver knows) and the physical units of the corrected output, so that an export converts to what
// its firmware expects (PX4: m/s^2, gauss, rad/s; ArduPilot: m/s^2, milligauss, rad/s; Kalibr and
// OpenVINS: SI) or refuses. Names are case-sensitive where SI makes them so: "mg" is a milli-g,
// "mG" a milligauss; "g" is standard gravity and a gauss is spelt "gauss" or "Gs".
#pragma once
#include <optional>
#include <string>
#include <string_view>

#include "numeric/calibration/instrument.hpp"

namespace scalcal {

enum class Quantity { acceleration, magnetic_field, angular_rate };

struct Unit {
  std::string_view name;  // canonical spelling
  Quantity quantity = Quantity::acceleration;
  double base = 1;  // this unit in the quantity's base unit: m/s^2, gauss, rad/s
};

// The unit of this name or one of its aliases ("m/s/s", "uT", "µT", "milligauss", "dps", ...).
std::optional<Unit> parse_unit(std::string_view name);
// "counts", "count", "LSB", "adc": raw units whose size in a physical unit the log does not say.
bool is_count_unit(std::string_view name);
// The known names, for messages.
std::string unit_names();

constexpr Quantity quantity_of(Instrument i) {
  return i == Instrument::accel ? Quantity::acceleration
         : i == Instrument::mag ? Quantity::magnetic_field
                                : Quantity::angular_rate;
}
std::string_view quantity_name(Quantity q);

// How many `to` one `from` is (same quantity).
inline double factor(const Unit& from, const Unit& to) { return from.base / to.base; }

// The unit a known magnitude is in, where the Earth leaves no doubt: gravity is 9.76-9.84 m/s^2
// everywhere on the surface (so 0.995-1.005 in g, 995-1005 in mg), the geomagnetic field 22-67 uT
// (0.22-0.67 gauss, 220-670 mG, 22000-67000 nT); ranges that do not overlap. Empty otherwise (a
// rate table's rate, a lab's field, a value in none of the ranges).
std::optional<Unit> unit_of_earth_magnitude(Instrument instrument, double magnitude);

// A size such as "0.061mg" or "0.0833 mG" or "1/16384 g": a value with its unit, as --raw-scale
// gives the driver's LSB. Empty when the text is not a positive finite number followed by a unit.
struct Amount {
  double value = 0;
  Unit unit;
};
std::optional<Amount> parse_amount(std::string_view text);

}  // namespace scalcal
