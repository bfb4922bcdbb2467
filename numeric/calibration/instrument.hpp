// The meter a calibration is of: what it measures and so how its log must be read. An accelerometer
// measures gravity only while it stands still (motion adds acceleration), so its positions are the
// still poses of a log; a magnetometer measures the same field however it moves, so every sample of
// a tumbling log is a position (MATLAB's magcal, PX4 and ArduPilot fit them all); a gyro measures
// the motion itself (a rate table's known rate).
#pragma once
#include <optional>
#include <string_view>

namespace scalcal {

enum class Instrument { accel, mag, gyro };

inline constexpr Instrument kInstruments[] = {Instrument::accel, Instrument::mag, Instrument::gyro};

constexpr std::string_view instrument_name(Instrument i) {
  return i == Instrument::accel ? "accel" : i == Instrument::mag ? "mag" : "gyro";
}

// What a person calls it, for messages.
constexpr std::string_view instrument_noun(Instrument i) {
  return i == Instrument::accel ? "accelerometer" : i == Instrument::mag ? "magnetometer" : "gyroscope";
}

constexpr std::optional<Instrument> parse_instrument(std::string_view s) {
  for (Instrument i : kInstruments)
    if (s == instrument_name(i)) return i;
  return std::nullopt;
}

// Whether the measured vector keeps its modulus while the meter moves, so that samples taken in
// motion are positions too.
constexpr bool field_survives_motion(Instrument i) { return i == Instrument::mag; }

}  // namespace scalcal
