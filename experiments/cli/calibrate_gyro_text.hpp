// The readable text of `scalcal calibrate --instrument gyro` (the CLI without --json): what the log
// held, the model and why (rate table, turns) or the accelerometer and the misfit (hand rotations),
// each parameter with its standard error, and the correction.
#pragma once
#include <string>

#include "commands/calibration/calibrate_gyro.hpp"

namespace scalcal::cli {

std::string calibrate_gyro_text(const commands::GyroCalibrateResult& result);

}  // namespace scalcal::cli
