// The scalar calibration of data in any units (ADC counts, a field of unknown strength): a
// closed-form ellipsoid start brings the measurements near the field's units, the paper's
// iterative estimator (eqs. 3-6) fits the remaining deviations, and the two compose into the full
// correction, physical = matrix (raw - offset), reported in the paper's convention too
// (numeric/calibration/full_correction.hpp). Data already within 10 % of the field's magnitude
// skip the start: their estimate is the paper's, bit for bit.
#pragma once
#include <string>
#include <vector>

#include "numeric/calibration/full_correction.hpp"
#include "numeric/calibration/scalar_calibration.hpp"

namespace scalcal {

struct AnyUnitsOptions {
  Modulus modulus = Modulus::norm;
  double magnitude = 1;         // |I| in physical units
  bool magnitude_auto = false;  // unknown field strength: the correction maps to unit modulus
  bool weight_by_samples = true;  // CalibrationOptions::weight_by_samples
};

struct PositionResidual {
  int line = 0;           // first sample's line
  double residual = 0;    // |corrected mean| / magnitude - 1
  double standardised = 0;  // by the residuals' own scale across positions and the position's leverage
};

struct AnyUnitsCalibration {
  bool started = false;                // the ellipsoid start was used (data not in the field's units)
  FullCorrection start;                // identity when not started
  CalibrationResult estimate;          // the paper's estimator on the start-corrected data
  FullCorrection correction;           // the final one, paper's convention
  double magnitude = 1;                // what the estimator used (1 with magnitude auto)
  double nominal_gain = 1;             // file units per physical unit the scale deviations are relative to
  Vec3 scale_deviation = Vec3::Zero();  // correction.scale / nominal_gain - 1
  Vec3 bias_std = Vec3::Zero(), scale_deviation_std = Vec3::Zero(), nonorthogonality_std = Vec3::Zero();
  std::vector<Vec3> directions;        // each position's corrected mean, normalised (the program measured)
  std::vector<PositionResidual> residuals;
  Vec9 achieved_std = Vec9::Zero();    // X's standard errors from the residuals' own scale across positions
  bool have_achieved = false;          // N > 9
};

// Throws InputError (file, 0, reason) when no start exists (no ellipsoid through the means), for
// the projection modulus on data not in the field's units, or as check_calibration_data does.
AnyUnitsCalibration calibrate_any_units(const std::string& file, const std::vector<PositionSamples>& data,
                                        const AnyUnitsOptions& options);

}  // namespace scalcal
