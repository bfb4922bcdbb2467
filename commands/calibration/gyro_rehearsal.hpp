// A gyro's rehearsal (simulate --instrument gyro --log): the log a gyro with random parameters would
// write on a program run on a rate table (each position the table's axis in the meter's frame,
// signed by the turn: an antipodal pair is one mounting turned both ways), as known turns (a turn of
// --turn-angle about each position), or by hand with an accelerometer (--accelerometer FILE: each
// position gravity's direction at a still pose), with the true parameters beside it. The meter:
// raw = offset + A Omega + white noise (--noise |I| per output and sample, |I| = --magnitude, the
// table's rate in rad/s; for hand rotations 1 rad/s), A = (E + dK) Phi with random parameters
// N(0, size^2) each (bias relative to |I|), and for hand rotations a rotation against the
// accelerometer of the same size; the accelerometer (hand rotations) as the accelerometer's
// rehearsal draws it, |g| = 9.80665 in its log's units.
#pragma once
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

#include "commands/core/json.hpp"
#include "commands/core/warning.hpp"
#include "numeric/gyro/gyro_simulation.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::commands {

struct GyroRehearsalRequest {
  std::string name;
  Program program;
  std::string method = "rate_table";  // rate_table, known_turns, hand_rotations
  double rate_hz = 100, dwell_s = 5;  // samples per second; seconds per segment (and at rest between)
  double noise = 1e-3;                // relative to |I|
  double magnitude = 1;               // the table's rate, rad/s
  double turn_angle_deg = 360;
  double size = 1e-3;
  std::optional<double> latitude_deg;  // rate table: add the Earth's rate (the table's axis vertical)
  std::uint64_t seed = 1;
};

struct GyroRehearsalResult {
  GyroRehearsalRequest request;
  gyro::GyroTruth truth;
  Meter accelerometer;  // hand rotations: the accelerometer's truth (raw = bias + gain f)
  gyro::SimulatedLog log;
  std::optional<RawLog> accelerometer_log;
  Warnings warnings;
};

GyroRehearsalResult rehearse_gyro(const GyroRehearsalRequest& request);

// instrument, method, offset, matrix (physical = matrix (raw - offset), rad/s), the paper's bias,
// scale_deviation and nonorthogonality (and rotation_to_accelerometer), noise, seed; for hand
// rotations the accelerometer's truth under "accelerometer" (offset, matrix, magnitude).
Json gyro_truth_json(const GyroRehearsalResult& result);

// CSV t,ix,iy,iz (and rate, the table's signed commanded rate, for a rate table).
void write_gyro_log(std::ostream& out, const RawLog& log, const std::vector<double>& rate);

}  // namespace scalcal::commands
