// The scalar calibration of data in any units (ADC counts, a field of unknown strength), for every
// registered model: a closed-form start (an ellipsoid no richer than the model: general for paper9,
// axis-aligned for axis6, a sphere for bias3) brings the measurements near the field's units, the
// model's iterative estimator (eqs. 3-6 with the model's row) fits the remaining deviations, and
// the two compose into the full correction, physical = matrix (raw - offset), reported in the
// paper's convention too (numeric/calibration/full_correction.hpp). Data already within 10 % of the
// field's magnitude skip the start. Every standard error is given twice: predicted from the noise
// within positions, and achieved from the residuals between positions; the larger is the one to use.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "numeric/calibration/full_correction.hpp"
#include "numeric/calibration/model_calibration.hpp"
#include "numeric/calibration/scalar_calibration.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal {

struct AnyUnitsOptions {
  Modulus modulus = Modulus::norm;
  double magnitude = 1;           // |I| in physical units
  bool magnitude_auto = false;    // unknown field strength: the correction maps to unit modulus
  bool weight_by_samples = true;  // CalibrationOptions::weight_by_samples
  ModelKind model = ModelKind::paper9;
  // One sample's noise covariance in file units (zero: none). Given, the fit's noise bias is
  // estimated from simulated copies and taken off (noise_bias.hpp): for single-sample positions
  // (a tumbling log), whose noise is not averaged away.
  Mat3 sample_noise = Mat3::Zero();
  std::uint64_t noise_bias_seed = 1;
};

struct PositionResidual {
  int line = 0;             // first sample's line
  double residual = 0;      // |corrected mean| / magnitude - 1
  double standardised = 0;  // by the residuals' own scale across positions and the position's leverage
};

struct AnyUnitsCalibration {
  ModelKind model = ModelKind::paper9;
  bool started = false;                 // the ellipsoid start was used (data not in the field's units)
  FullCorrection start;                 // identity when not started
  ModelCalibration estimate;            // the model's estimator on the start-corrected data
  FullCorrection correction;            // the final one, paper's convention (cubic12: its linear part)
  bool linear = true;                   // false for a model with a nonlinear term (cubic12)
  double magnitude = 1;                 // what the estimator used (1 with magnitude auto)
  double nominal_gain = 1;              // file units per physical unit the scale deviations are relative to
  double nominal_gain_std = NAN;        // its standard error (the common part of the scale deviations)
  Vec3 scale_deviation = Vec3::Zero();  // correction.scale / nominal_gain - 1
  Vec3 gain = Vec3::Ones();             // correction.scale: file units per physical unit (per field strength with auto)
  Vec3 gain_std = Vec3::Constant(NAN);  // its standard error (the larger of predicted and achieved); NaN for bias3
  // The noise bias taken off (sample_noise given): the refits that estimated it (0: none taken off),
  // and what it moved the offsets and the gains by, in file units (estimate before - after).
  int noise_bias_replicates = 0;
  Vec3 offset_noise_bias = Vec3::Zero(), gain_noise_bias = Vec3::Zero();

  // Standard errors of the model's parameters (model order) in the reported units: bias in file
  // units, scale deviation relative to the nominal gain, non-orthogonality in rad, cubic as c |I|.
  // NaN where not estimable (predicted: one sample per position and N = P; achieved: N = P).
  Eigen::VectorXd predicted_std, achieved_std, standard_error;  // standard_error: the larger of the two
  int dof = 0;                                                  // positions minus parameters
  // standard_error for the meter's nine linear parameters (NaN for those the model does not have).
  Vec3 bias_std = Vec3::Constant(NAN), scale_deviation_std = Vec3::Constant(NAN),
       nonorthogonality_std = Vec3::Constant(NAN);
  std::vector<Vec3> directions;  // each position's corrected mean, normalised (the program measured)
  std::vector<PositionResidual> residuals;
  // The residuals against the noise within positions: chi-square with dof degrees of freedom (only
  // when the noise comes from the scatter of repeated samples and dof > 0).
  std::optional<double> chi_square;
  double chi_square_p = 1;
  // The error model (between_poses.hpp), when the noise comes from the scatter within positions and
  // positions outnumber parameters: the between-pose scatter sigma_b and the within one sigma_w (of
  // one sample), both in the units of the magnitude; each residual standardised under the model. Its
  // covariance gives standard_error (model_std) where it exists.
  double between_std = NAN, within_std = NAN;
  std::vector<double> model_standardised;
  Eigen::VectorXd model_std;  // empty without the error model
  // The noise-based covariance (the scatter within positions, or a tumbling log's second
  // differences), empty when there is none; the estimator's units.
  Eigen::MatrixXd noise_covariance;
  // The covariance standard_error comes from, in the estimator's units (bias / |I|, dk, gamma,
  // c |I|): the error model's, else the residual-based, else the noise-based one.
  Eigen::MatrixXd covariance;
};

// Each of the model's parameters (model order) in the reported units, by its group in the meter: bias in file
// units, scale deviation relative to the nominal gain, non-orthogonality in rad, cubic as c |I|.
Eigen::VectorXd reported_values(const AnyUnitsCalibration& fit);

// Throws InputError (file, 0, reason): fewer positions than parameters, no start (no ellipsoid
// through the means), the projection modulus or cubic12 on data not in the field's units, a
// rank-deficient or ill-conditioned layout (beyond kIllConditioned), a degenerate correction.
AnyUnitsCalibration calibrate_any_units(const std::string& file, const std::vector<PositionSamples>& data,
                                        const AnyUnitsOptions& options);

// The standard errors from covariances of the estimator's parameters (bias / |I|, dk, gamma, c |I|;
// empty: not estimable): predicted_std, achieved_std, model_std, then standard_error: the error
// model's where it is given, else the larger of the other two; the meter's nine and the gains' from
// the same. calibrate_any_units calls it; a caller with a better covariance (residuals correlated in
// time) calls it again.
void assign_errors(AnyUnitsCalibration& fit, const Eigen::MatrixXd& predicted, const Eigen::MatrixXd& achieved,
                   const Eigen::MatrixXd& model = Eigen::MatrixXd());

}  // namespace scalcal
