// The readable text of `scalcal calibrate` (the CLI without --json): what was found, the model and
// why, each parameter with the standard error to use (the larger of the noise-based and the
// residual-based, named), the gain, the worst positions, and what to add.
#pragma once
#include <string>

#include "commands/calibration/calibrate.hpp"

namespace scalcal::cli {

std::string calibrate_text(const commands::CalibrateResult& result);

// Each warning as one stderr line, "scalcal COMMAND: SUBJECT: warning: MESSAGE".

}  // namespace scalcal::cli
