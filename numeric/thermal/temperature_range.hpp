// The temperatures a thermal program spans, [T1, T2] in degrees Celsius, and the normalised coordinate
// tau = (T - T_mid) / half-range in [-1, 1] that the thermal models' polynomials are written in (the
// polynomial-regression literature's interval, where the optimal set-points have closed forms).
#pragma once
#include <string>

namespace scalcal {

struct TemperatureRange {
  double low = 0, high = 0;  // degrees Celsius, low < high

  double middle() const { return (low + high) / 2; }
  double half_range() const { return (high - low) / 2; }
  double tau(double celsius) const { return (celsius - middle()) / half_range(); }
  double celsius(double tau) const { return middle() + half_range() * tau; }
  std::string text() const;  // "-20..60", the form parse_temperature_range() reads
};

// "T1..T2" (degrees Celsius, T1 < T2, both within -273.15..1000); throws std::invalid_argument with
// the reason otherwise (the front end names its option).
TemperatureRange parse_temperature_range(const std::string& text);

}  // namespace scalcal
