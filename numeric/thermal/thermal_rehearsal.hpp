// A thermal rehearsal (simulate --model BASE+Tk --temperature T1..T2 --log FILE): the raw log a meter
// whose nine parameters drift as polynomials in temperature would write on a thermal program run in its
// order, with the truth. The meter rests --dwell seconds at each row's position and temperature, and
// moves between rows along the great circle (cosine profile, 45 degrees per second, at least one
// second; two rows less than 5 degrees apart get a 20-degree swing between them, so they stay two
// poses); the temperature goes linearly from one row's to the next's during the move (the oven's soak
// is not logged). Raw = bias(T) + gain(T) |I| eta + white noise of `noise` |I| per output; the
// temperature column is exact. The truth: X_0 ~ N(0, size^2) and each drift coefficient of tau^j
// ~ N(0, drift^2), from the seed. A ramp (ramp_c_per_min > 0) ignores the rows' temperatures: the
// temperature climbs from T1 at that rate, during rests and moves alike, while the meter runs the program's
// positions over and over, until the rest in which it reaches T2 ends.
#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "numeric/thermal/thermal_program.hpp"

namespace scalcal {

struct ThermalRehearsalRequest {
  ThermalProgram program;
  ThermalModel model;  // BASE paper9
  TemperatureRange range;
  double rate_hz = 100, dwell_s = 5;
  double noise = 1e-3, magnitude = 1, size = 1e-3, drift = 1e-3;
  double ramp_c_per_min = 0;  // > 0: a ramp from range.low to range.high instead of the rows' set-points
  std::uint64_t seed = 1;
};

struct ThermalRehearsal {
  Eigen::VectorXd truth;  // model.parameter_names() order, coefficients of tau^j
  std::vector<double> t, celsius;
  std::vector<Eigen::Vector3d> samples;
  std::vector<int> row;  // 1-based program row of each sample, 0 while moving
};

// The most samples the rehearsal of `request` can write (a rest and the longest move per row, or the ramp's
// duration and one more row), the bound rehearse_thermal() holds to 2e7.
inline constexpr double kMaxThermalRehearsalSamples = 2e7;
double thermal_rehearsal_samples(const ThermalRehearsalRequest& request);

// Throws std::invalid_argument for a base other than paper9, a rate outside 1e-3..1e6 Hz or more than
// 2e7 samples.
ThermalRehearsal rehearse_thermal(const ThermalRehearsalRequest& request);

}  // namespace scalcal
