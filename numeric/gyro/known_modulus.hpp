// Scalar calibration of a gyro from items of known modulus: a rate table's segment (its mean output,
// the table's rate: Theorem 24 of proofs/gyro_rate_table.md, the accelerometer's model with the
// table's axis as the position) and a known turn (its integrated output over the turn, divided by
// the turn's duration, whose modulus is the angle over the duration: the bias enters through the
// duration). The meter is eq. (2)'s, raw = o + diag(k) Phi(gamma) Omega, fitted in the paper's
// parameters (o in raw units, k in raw units per physical unit, gamma in rad) by weighted least
// squares on |Omega_i| - mu_i, with a rate per item (so per-segment rates, the Earth's rate added
// to each, and turns of different durations need nothing else), and the rests' mean outputs as
// observations of o. Groups and their weights as in grouped_least_squares.hpp. With the modulus
// unknown (`auto`, as for magnetometers) every mu_i is relative and the gain is per unit of it.
#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>

#include "numeric/calibration/full_correction.hpp"
#include "numeric/calibration/meter_model.hpp"
#include "numeric/gyro/rate_segments.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/summary.hpp"

namespace scalcal::gyro {

struct ModulusItem {
  Vec3 mean = Vec3::Zero();    // raw units: a segment's mean output, a turn's integral over its seconds
  double modulus = 1;          // known |Omega| in physical units (a turn: angle / seconds)
  double noise = 1;            // predicted standard error of `mean` along its direction, raw units
  int line = 0;                // first line in the file
  double start = 0, stop = 0;  // seconds, for reports
};

// The items of a rate table: each segment with its rate (rates.size() == segments or 1).
std::vector<ModulusItem> segment_items(const std::vector<LogInterval>& segments, const std::vector<double>& rates);
// The items of known turns: each turn with its angle (angles.size() == turns or 1, physical units of
// angle, e.g. rad for rad/s).
std::vector<ModulusItem> turn_items(const std::vector<Turn>& turns, const std::vector<double>& angles,
                                    double sample_noise, double sample_period);

struct KnownModulusOptions {
  ModelKind model = ModelKind::paper9;  // paper9, axis6 (gamma = 0) or bias3 (one gain)
  int max_iterations = 100;
};

// Parameter order: o (3), k (3), gamma (3).
inline constexpr int kGyroParameters = 9;

struct KnownModulusCalibration {
  ModelKind model = ModelKind::paper9;
  Meter meter;                // bias o, scale_deviation k - 1, misalignment gamma / 2 (rotation part zero)
  FullCorrection correction;  // physical = matrix (raw - offset)
  Eigen::Matrix<double, 9, 1> parameters = Eigen::Matrix<double, 9, 1>::Zero();
  Eigen::Matrix<double, 9, 1> standard_error = Eigen::Matrix<double, 9, 1>::Constant(NAN);  // NaN: not estimated
  Eigen::Matrix<double, 9, 1> predicted_std = Eigen::Matrix<double, 9, 1>::Constant(NAN);
  Eigen::Matrix<double, 9, 9> covariance = Eigen::Matrix<double, 9, 9>::Zero();
  std::vector<double> residuals;          // |corrected item| - modulus, physical units
  std::vector<Vec3> directions;           // each item's corrected direction: the program measured
  double item_scale = 1, rest_scale = 1;  // achieved / predicted variance
  double item_dof = 0, rest_dof = 0;
  double condition = 0;  // of the scaled normal matrix
  int iterations = 0;
  Summary summary;
};

// Throws InputError (file, 0, reason) with fewer items and rests than the model's unknowns, or items
// whose directions cannot carry the model (the reason names what is missing).
KnownModulusCalibration calibrate_known_moduli(const std::string& file, const std::vector<ModulusItem>& items,
                                               const std::vector<LogInterval>& rests,
                                               const KnownModulusOptions& options = {});

}  // namespace scalcal::gyro

namespace scalcal::gyro {

// The items' directions before the fit (through the start: the rests' offset, one gain per axis),
// the program the layout is judged on.
std::vector<Vec3> item_directions(const std::vector<ModulusItem>& items, const std::vector<LogInterval>& rests);

// --model auto: the accelerometer's choice (numeric/calibration/model_choice.hpp: the richest of
// paper9, axis6, bias3 the directions carry), with its reason. Throws InputError when none does.
KnownModulusCalibration calibrate_known_moduli_auto(const std::string& file, const std::vector<ModulusItem>& items,
                                                    const std::vector<LogInterval>& rests, std::string& reason);

}  // namespace scalcal::gyro
