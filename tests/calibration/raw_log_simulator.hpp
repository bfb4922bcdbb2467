// A raw logger simulated for the tests only, apart from the estimator and the interval detector:
// a meter (independent_simulator.hpp's eq. 2 by components) read out in ADC counts, held still in
// a sequence of directions with hand-like motion between them, sampled at a fixed rate with
// Gaussian noise. The still segments are known exactly, so detection and calibration can be
// judged against the truth.
#pragma once
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "tests/calibration/independent_simulator.hpp"

namespace calibration_test {

struct StillSegment {
  double start = 0, end = 0;  // seconds
  V3 direction{};
};

struct SimulatedLog {
  std::string text;  // "t ix iy iz" lines (or "ix iy iz" without the time column)
  std::vector<StillSegment> still;
};

struct LogSpec {
  TrueMeter meter;                                 // in units of the field
  double magnitude = 9.81;                         // the field
  double zero = 32768, counts_per_unit = 400;      // raw = zero + counts_per_unit * meter.measure(I)
  double noise = 2.0;                              // counts, per sample and output
  double quantum = 1.0;                            // the ADC's step: outputs are whole multiples of it
  double rate = 100;                               // Hz
  double first_still = 40, still = 6, motion = 3;  // seconds
  double lead_motion = 0;   // seconds of motion before the first still segment (a log without a still start)
  bool time_column = true;  // false: "ix iy iz" lines, the time only in the rate
  std::uint64_t seed = 7;
};

inline V3 unit(V3 v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

// Still in each of `directions` in turn (the first for first_still seconds), moving between them
// along the great circle with a wobble of 20 degrees, as a hand would.
inline SimulatedLog simulate_log(const LogSpec& spec, const std::vector<V3>& directions) {
  SimulatedLog out;
  std::mt19937_64 rng(spec.seed);
  std::normal_distribution<double> gauss(0.0, spec.noise);
  const double dt = 1.0 / spec.rate;
  double t = 0;
  char line[160];
  const auto emit = [&](const V3& d) {
    const V3 I{spec.magnitude * d[0], spec.magnitude * d[1], spec.magnitude * d[2]};
    const V3 m = spec.meter.measure(I);
    const auto adc = [&](double v) {
      return spec.quantum * std::round((spec.zero + spec.counts_per_unit * v + gauss(rng)) / spec.quantum);
    };
    if (spec.time_column)
      std::snprintf(line, sizeof line, "%.6f %.10g %.10g %.10g\n", t, adc(m[0]), adc(m[1]), adc(m[2]));
    else
      std::snprintf(line, sizeof line, "%.10g %.10g %.10g\n", adc(m[0]), adc(m[1]), adc(m[2]));
    out.text += line;
    t += dt;
  };
  // Lead motion: tumbling about the first direction before the log's first still segment.
  const int lead = static_cast<int>(spec.lead_motion * spec.rate);
  for (int s = 0; s < lead && !directions.empty(); ++s) {
    const double u = (s + 1.0) / lead, a = 2.5 * std::sin(6.0 * u), b = 1.5 * std::cos(4.0 * u);
    emit(unit({std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), std::sin(b)}));
  }
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const V3 d = unit(directions[k]);
    if (k > 0) {  // motion from the previous direction
      const V3 a = unit(directions[k - 1]);
      const int steps = static_cast<int>(spec.motion * spec.rate);
      for (int s = 0; s < steps; ++s) {
        const double u = (s + 1.0) / (steps + 1.0), wobble = 0.35 * std::sin(3.14159265 * u) * std::sin(17.0 * u);
        V3 v{a[0] * (1 - u) + d[0] * u + wobble, a[1] * (1 - u) + d[1] * u - wobble,
             a[2] * (1 - u) + d[2] * u + 0.5 * wobble};
        emit(unit(v));
      }
    }
    const double length = k == 0 ? spec.first_still : spec.still;
    StillSegment seg{t, 0, d};
    const int steps = static_cast<int>(length * spec.rate);
    for (int s = 0; s < steps; ++s) emit(d);
    seg.end = t - dt;
    out.still.push_back(seg);
  }
  return out;
}

// 14 directions: the six axes and the eight cube diagonals (a 14-position program).
inline std::vector<V3> fourteen_directions() {
  std::vector<V3> p = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (double a : {1.0, -1.0})
    for (double b : {1.0, -1.0})
      for (double c : {1.0, -1.0}) p.push_back({a, b, c});
  return p;
}

}  // namespace calibration_test
