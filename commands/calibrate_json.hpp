// The JSON form of `calibrate`'s result (--json, the Python dict) and of the calibration file that
// `calibrate --out` writes and `correct` reads. One schema for every model: the meter's bias (file
// units), scale deviations (relative to the nominal gain) and non-orthogonality (rad) always, null
// standard errors for what the model does not estimate, and the model's own parameters by name.
#pragma once
#include "commands/calibrate.hpp"
#include "commands/json.hpp"

namespace scalcal::commands {

Json to_json(const CalibrateResult& result);

// The calibration file: what `correct` needs (offset, matrix, converged, model) and the whole
// result beside it. The one writer of the format, for issue 32 to extend (version, units, sensor).
Json calibration_file_json(const CalibrateResult& result);

}  // namespace scalcal::commands
