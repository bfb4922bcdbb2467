// Simulated gyro logs with their truth, for `simulate --instrument gyro --log` and for the coverage
// tests: a rate table (segments at known rates about axes fixed in the meter, rests between, the
// Earth's rate optional), known turns (a turntable or a flat table turned by a known angle, rests
// between) and hand rotations (an accelerometer and a gyro moved between random still poses, each
// motion about two axes at once so that the rotations do not commute). The gyro reads
// raw = offset + A Omega + white noise, with Omega in the simulation's physical frame, which is also
// the accelerometer's corrected frame (its meter has no rotation part, as scalar calibration takes
// it), so the true correction is C = A^-1, offset. The motion is integrated 16 times finer than
// the log's rate.
#pragma once
#include <cstdint>
#include <vector>

#include "numeric/calibration/meter_model.hpp"
#include "numeric/calibration/raw_log.hpp"

namespace scalcal::gyro {

inline constexpr double kEarthRate = 7.292115e-5;  // rad/s, the Earth's sidereal rate

struct GyroTruth {
  Mat3 gain = Mat3::Identity();  // A: raw units per physical unit (rad/s)
  Vec3 offset = Vec3::Zero();    // raw units
  double noise = 0;              // one sample's standard deviation per axis, raw units
  Mat3 correction() const { return gain.inverse(); }
};

// A segment of a rate-table plan: the table's axis in the meter's frame (the mounting), the signed
// rate about it (rad/s; negative: the table reversed) and how long it runs.
struct TableSegment {
  Vec3 axis = Vec3::UnitZ();
  double rate = 1;
  double seconds = 10;
};

struct SimulatedLog {
  RawLog log;
  std::vector<double> rate;  // per sample: the table's commanded signed rate (rate tables; else empty)
};

struct RateTableSimulation {
  double sample_rate = 100;    // Hz
  double rest_seconds = 5;     // before, between and after the segments
  double spin_up_seconds = 1;  // the table accelerates and stops within this (logged as motion)
  bool earth = false;          // add the Earth's rate (table axis vertical, latitude below)
  double latitude_deg = 45;
};

// Throws std::invalid_argument for a non-unit axis or non-positive durations.
SimulatedLog simulate_rate_table(const GyroTruth& truth, const std::vector<TableSegment>& plan,
                                 const RateTableSimulation& options, std::uint64_t seed);

// A known turn: the axis in the meter's frame, the angle (rad, signed) and its duration.
struct KnownTurn {
  Vec3 axis = Vec3::UnitZ();
  double angle = 2 * M_PI;
  double seconds = 4;
};

SimulatedLog simulate_known_turns(const GyroTruth& truth, const std::vector<KnownTurn>& turns, double sample_rate,
                                  double rest_seconds, std::uint64_t seed);

struct HandRotationSimulation {
  int poses = 30;
  double sample_rate = 100;
  double gravity = 9.81;
  Meter accelerometer;  // raw_a = bias + gain f (f in the physical frame)
  double accelerometer_noise = 0;
  double min_rest_seconds = 2, max_rest_seconds = 5;
  double min_motion_seconds = 1.5, max_motion_seconds = 3;
};

struct HandRotationLogs {
  RawLog accelerometer, gyro;  // the same time stamps
};

HandRotationLogs simulate_hand_rotations(const GyroTruth& truth, const HandRotationSimulation& options,
                                         std::uint64_t seed);

// Hand rotations through given poses: gravity's direction in the meter's frame at each (unit
// vectors, a program's positions), each motion a turn about gravity (a random yaw of up to 60
// degrees, which the accelerometer cannot see) and then the tilt that carries one direction into
// the next, two phases about different axes.
HandRotationLogs simulate_hand_rotations_through(const GyroTruth& truth, const std::vector<Vec3>& gravity_directions,
                                                 const HandRotationSimulation& options, std::uint64_t seed);

// A gyro like an Xsens MTi's: about 4800 counts per rad/s around 32768, a few per mille of scale
// error, non-orthogonality and rotation against the accelerometer, 27 counts of noise. `rotated`:
// with a rotation part (hand rotations see it; a rate table does not).
GyroTruth reference_gyro(bool rotated);

}  // namespace scalcal::gyro
