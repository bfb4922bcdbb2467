// What a model states about its exact limits: for each criterion the infimum of the normalised
// criterion over all measures on the sphere (closed form and value), the optimal measure, and which
// N attain it, each proven in the proof document the model names.
#pragma once
#include <limits>
#include <string_view>

namespace scalcal {

inline constexpr double kNotDetermined = std::numeric_limits<double>::quiet_NaN();

struct ModelLimit {
  std::string_view criterion;  // "D", "A", "E", "S"
  double value;                // the infimum, normalised (D by N^P)
  std::string_view exact;      // the infimum in closed form
  // Moments of the optimal measure symmetrised over the 48 signed permutations, in closed form
  // ("" where the limit does not determine them or the model has no such moment).
  std::string_view x4;        // E[x^4]
  std::string_view x2y2;      // E[x^2 y^2]
  std::string_view x6;        // E[x^6]
  double b;                   // E[x^2 y^2] as a number (NaN: not determined)
  std::string_view measure;   // the optimal measure in words
  std::string_view attained;  // which N attain it, and how sure that is
  // Where the optimal measure is weight w on the 6 axis directions and 1 - w on the 8 cube diagonals
  // (evenly within each), w; NaN where it has no such form. The multistart rounds it to N positions
  // for a start (synthesis/rounded_start.hpp).
  double axis_weight = kNotDetermined;
  // Whether the multistart's starts after the first are randomised roundings of that measure
  // (synthesis/rounded_start.hpp) instead of random programs: set where they were measured to find
  // better optima at a fraction of a random start's cost.
  bool rounding_starts = false;
};

}  // namespace scalcal
