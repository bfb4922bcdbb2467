// The JSON form of `calibrate`'s result (--json, the Python dict) and of the calibration file that
// `calibrate --out` writes and `correct` reads. One schema for every model; one name per quantity:
//   model, model_reason, not_identifiable   the model fitted, why, and what the layout or the data
//                                           cannot determine (parameter names, or a sentence)
//   converged, termination, message, iterations   the fit's Summary
//   bias (file units), scale_deviation (relative to nominal_gain), nonorthogonality (rad): the
//       meter's nine linear parameters for every model (0 where the model has none)
//   bias_std, scale_deviation_std, nonorthogonality_std: their standard errors, the larger of the
//       noise-based and the residual-based (null where the model does not estimate them)
//   parameters, predicted_std, achieved_std, std_from: the model's own parameters by name, in the
//       same units as above (cubic terms as c |I|); predicted from the noise within positions,
//       achieved from the residuals between them; std_from says which is the larger
//   dof (positions minus parameters), t95 (Student's t at 95 %), chi_square (the residuals against
//       the noise within positions, with chi_square_dof and chi_square_p)
//   gain, gain_std: file units per physical unit (per field strength with --magnitude auto);
//       field_strength, field_strength_std: |I| in file units with --magnitude auto
//   offset, matrix: physical = matrix (raw - offset); null matrix for a nonlinear model (linear false)
//   intervals: each position's start, end (seconds, null for bench data), samples, mean (raw),
//       direction (unit vector in the meter's frame after calibration), residual (|corrected mean|
//       - |I|, physical units) and standardised_residual
//   program (the measured directions under the model), suggested (positions to add, never twice)
#pragma once
#include "commands/calibration/calibrate.hpp"
#include "commands/calibration/calibration_file.hpp"
#include "commands/core/json.hpp"

namespace scalcal::commands {

Json to_json(const CalibrateResult& result);

// The calibration file: format_version, created (UTC, ISO 8601), tool {name, version, commit},
// sensor (--sensor, null when not given), units {raw, physical} (--units, null when not given),
// region (where the program was judged), then the whole result: what `correct` needs (offset,
// matrix, converged, model), magnitude, and the rest. The one writer of the format.
Json calibration_file_json(const CalibrateResult& result);

}  // namespace scalcal::commands
