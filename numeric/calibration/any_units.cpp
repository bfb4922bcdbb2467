// Any units, any registered model: the start, the model's estimator, the composed correction and
// the two standard errors of every parameter.
#include "numeric/calibration/any_units.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>
#include <boost/math/distributions/chi_squared.hpp>

#include "numeric/calibration/between_poses.hpp"
#include "numeric/calibration/noise_bias.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal {
namespace {

// Within this of the magnitude (median over positions) the data are in the field's units.
constexpr double kInUnits = 0.1;
// Degrees of freedom from which the between-pose variance is estimated (REML): with fewer, one
// variance from a handful of residuals would be guessed, and the larger of the noise-based and the
// residual-based standard errors stands (with Student's t).
constexpr int kErrorModelDof = 5;

double median_modulus_ratio(const std::vector<PositionSamples>& data, double magnitude) {
  std::vector<double> r;
  for (const auto& p : data) r.push_back(p.mean().norm() / magnitude);
  std::nth_element(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(r.size() / 2), r.end());
  return r[r.size() / 2];
}

Mat3 block(const Eigen::MatrixXd& cov, const std::vector<int>& at) {
  Mat3 b;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) b(i, j) = cov(at[static_cast<std::size_t>(i)], at[static_cast<std::size_t>(j)]);
  return b;
}

// A covariance of the estimator's parameters (bias / |I|, dk, gamma, c |I|) as the standard errors
// of the reported ones: bias in file units through the start (first order: the start is a fixed
// map), scale deviations relative to their geometric mean when the start set the nominal gain.
Eigen::VectorXd reported_std(const Eigen::MatrixXd& cov, const MeterSlots& slots, const AnyUnitsCalibration& a) {
  Eigen::VectorXd out = cov.diagonal().cwiseMax(0.0).cwiseSqrt();
  if (const auto b = meter_group(slots, ParameterGroup::bias); !b.empty()) {
    const Mat3 T_inverse = a.started ? Mat3(a.start.matrix.inverse()) : Mat3::Identity();
    const Mat3 c = a.magnitude * a.magnitude * T_inverse * block(cov, b) * T_inverse.transpose();
    for (int i = 0; i < 3; ++i) out(b[static_cast<std::size_t>(i)]) = std::sqrt(std::max(c(i, i), 0.0));
  }
  if (const auto s = meter_group(slots, ParameterGroup::scale); !s.empty() && a.started) {
    const Mat3 P = Mat3::Identity() - Mat3::Constant(1.0 / 3);
    const Mat3 c = P * block(cov, s) * P.transpose();
    for (int i = 0; i < 3; ++i) out(s[static_cast<std::size_t>(i)]) = std::sqrt(std::max(c(i, i), 0.0));
  }
  return out;
}

using RowFunction = Eigen::VectorXd (*)(const Vec3&);
template <class Model>
Eigen::VectorXd dynamic_row(const Vec3& eta) {
  return Model::row(eta);
}

// The start, applied to every sample; throws when the data cannot have one.
std::vector<PositionSamples> started_data(const std::string& file, const std::vector<PositionSamples>& data,
                                          const AnyUnitsOptions& options, const MeterSlots& slots, double ratio,
                                          AnyUnitsCalibration& out) {
  const std::string name(model_name(options.model));
  if (options.modulus == Modulus::projection)
    throw InputError(
        file, 0,
        "the measured modulus is " + std::to_string(ratio) +
            words(" times {magnitude}; the projection modulus needs data in the field's units (use the norm "
                  "modulus, which starts from an ellipsoid fit in any units)"));
  if (!corrects_linearly(slots))
    throw InputError(file, 0,
                     "the measured modulus is " + std::to_string(ratio) + words(" times {magnitude}: {model} ") + name +
                         " calibrates data in the field's units only (" +
                         std::string(meter_units_bound(options.model)) +
                         "); the linear models start from an ellipsoid fit in any units");
  const EllipsoidShape shape = has_meter_group(slots, ParameterGroup::nonorth) ? EllipsoidShape::general
                               : has_meter_group(slots, ParameterGroup::scale) ? EllipsoidShape::axis_aligned
                                                                               : EllipsoidShape::sphere;
  std::vector<Vec3> means;
  for (const auto& p : data) means.push_back(p.mean());
  const auto start = fit_ellipsoid(means, out.magnitude, shape);
  if (!start)
    throw InputError(file, 0,
                     "no ellipsoid passes near the " + std::to_string(data.size()) +
                         " positions' means: they are too few or too flat for a start in any units");
  out.start = *start;
  std::vector<PositionSamples> y = data;
  for (auto& p : y)
    for (auto& s : p.samples) s = out.start.apply(s);
  return y;
}

void check_layout(const std::string& file, const std::vector<PositionSamples>& y, const AnyUnitsOptions& options,
                  double M) {
  const double ratio = median_modulus_ratio(y, M);
  if (ratio < 0.5 || ratio > 2.0)
    throw InputError(file, 0,
                     "the measured modulus is " + std::to_string(ratio) + words(" times {magnitude} ") +
                         std::to_string(M) + words("; the model needs it near 1 (wrong {magnitude} or units?)"));
  const ModelEvaluation ev = evaluate(options.model, Program{position_directions(y, options.modulus)});
  if (!ev.full_rank()) throw InputError(file, 0, "the measured positions form a " + rank_deficiency(ev));
  if (ev.condition > kIllConditioned)
    throw InputError(file, 0, "the measured positions form an " + ill_conditioning(ev));
}

// The final correction, its gain and the scale deviations relative to it.
void compose(const std::string& file, AnyUnitsCalibration& out) {
  const Meter& meter = out.estimate.meter.linear();
  const FullCorrection second = correction_of(meter);
  if (!out.started) {
    out.correction = second;
  } else {
    // physical = G^-1 (y - Delta), y = T (raw - o): matrix G^-1 T, offset o + T^-1 Delta.
    const auto canonical = canonical_correction(second.matrix * out.start.matrix,
                                                out.start.offset + out.start.matrix.inverse() * meter.bias);
    if (!canonical) throw InputError(file, 0, "the fitted correction is degenerate (two sensor axes nearly parallel)");
    out.correction = *canonical;
    out.nominal_gain = std::cbrt(out.correction.scale.prod());
  }
  out.gain = out.correction.scale;
  out.scale_deviation = out.correction.scale / out.nominal_gain - Vec3::Ones();
}

// The larger of the noise-based and the residual-based standard error (either may be NaN: not
// estimable).
double larger(double p, double a) { return std::isnan(p) ? a : std::isnan(a) ? p : std::max(p, a); }

// The gains' standard errors by the delta method: gain_i = nominal gain (1 + dk_i), so its relative
// error is dk_i's, common part included; with --magnitude auto too (|corrected| = 1 fixes the gains'
// common scale: the field's strength in file units), where only the scale deviations, relative to
// the gains' geometric mean, lose the common part (reported_std's projection). The nominal gain's
// (the field's strength in file units with magnitude auto) moves with the mean scale deviation:
// var = 1^T C 1 / 9. Each the larger of the two covariances given (empty: not estimable).
void gain_errors(AnyUnitsCalibration& out, const MeterSlots& slots, const Eigen::MatrixXd& predicted,
                 const Eigen::MatrixXd& achieved) {
  const auto sb = meter_group(slots, ParameterGroup::scale);
  if (sb.empty()) return;
  const auto gain_std = [&](const Eigen::MatrixXd& cov) {
    if (cov.size() == 0) return Vec3(Vec3::Constant(NAN));
    return Vec3(out.gain.cwiseProduct(block(cov, sb).diagonal().cwiseMax(0.0).cwiseSqrt()));
  };
  const auto mean_std = [&](const Eigen::MatrixXd& cov) {
    return cov.size() == 0 ? NAN : out.nominal_gain * std::sqrt(std::max(block(cov, sb).sum(), 0.0)) / 3;
  };
  out.nominal_gain_std = larger(mean_std(predicted), mean_std(achieved));
  const Vec3 p = gain_std(predicted), a = gain_std(achieved);
  for (int i = 0; i < 3; ++i) out.gain_std(i) = larger(p(i), a(i));
}

}  // namespace

void assign_errors(AnyUnitsCalibration& out, const Eigen::MatrixXd& predicted, const Eigen::MatrixXd& achieved,
                   const Eigen::MatrixXd& model) {
  const MeterSlots slots = meter_slots(out.model);
  const auto P = static_cast<Eigen::Index>(slots.size());
  const Eigen::VectorXd nan = Eigen::VectorXd::Constant(P, NAN);
  out.predicted_std = predicted.size() ? reported_std(predicted, slots, out) : nan;
  out.achieved_std = achieved.size() ? reported_std(achieved, slots, out) : nan;
  out.model_std = model.size() ? reported_std(model, slots, out) : Eigen::VectorXd();
  out.covariance = model.size() ? model : achieved.size() ? achieved : predicted;
  out.noise_covariance = predicted;
  out.standard_error =
      model.size() ? out.model_std
                   : out.predicted_std.binaryExpr(out.achieved_std, [](double p, double a) { return larger(p, a); });
  for (Eigen::Index k = 0; k < P; ++k) {
    const MeterParameter& m = slots[static_cast<std::size_t>(k)].parameter;
    if (m.group == ParameterGroup::bias)
      out.bias_std(m.axis) = out.standard_error(k);
    else if (m.group == ParameterGroup::scale)
      out.scale_deviation_std(m.axis) = out.standard_error(k);
    else if (m.group == ParameterGroup::nonorth)
      out.nonorthogonality_std(m.axis) = out.standard_error(k);
  }
  if (model.size())
    gain_errors(out, slots, model, Eigen::MatrixXd());
  else
    gain_errors(out, slots, predicted, achieved);
}

Eigen::VectorXd reported_values(const AnyUnitsCalibration& a) {
  const MeterSlots slots = meter_slots(a.model);
  Eigen::VectorXd v(static_cast<Eigen::Index>(slots.size()));
  for (std::size_t k = 0; k < slots.size(); ++k) {
    const MeterParameter& m = slots[k].parameter;
    const auto i = static_cast<Eigen::Index>(k);
    v(i) = m.group == ParameterGroup::bias      ? a.correction.offset(m.axis)
           : m.group == ParameterGroup::scale   ? a.scale_deviation(m.axis)
           : m.group == ParameterGroup::nonorth ? a.correction.nonorthogonality(m.axis)
                                                : a.estimate.X(i);
  }
  return v;
}

AnyUnitsCalibration calibrate_any_units(const std::string& file, const std::vector<PositionSamples>& data,
                                        const AnyUnitsOptions& options) {
  AnyUnitsCalibration out;
  out.model = options.model;
  out.magnitude = options.magnitude_auto ? 1.0 : options.magnitude;
  const double M = out.magnitude;
  const MeterSlots slots = meter_slots(options.model);
  const int P = static_cast<int>(slots.size());
  const int n = static_cast<int>(data.size());
  if (n < P)
    throw InputError(file, 0,
                     std::to_string(n) + " positions cannot identify the " + std::to_string(P) +
                         words(" parameters of {model} ") + std::string(model_name(options.model)));
  const double ratio = median_modulus_ratio(data, M);
  out.started = options.magnitude_auto || std::abs(ratio - 1) > kInUnits;
  const std::vector<PositionSamples> y = out.started ? started_data(file, data, options, slots, ratio, out) : data;
  check_layout(file, y, options, M);
  CalibrationOptions co;
  co.modulus = options.modulus;
  co.magnitude = M;
  co.weight_by_samples = options.weight_by_samples;
  out.estimate = calibrate_model(options.model, y, co);
  const ModelCalibration& r = out.estimate;
  out.linear = corrects_linearly(slots);
  compose(file, out);
  if (!options.sample_noise.isZero()) {
    const Mat3 S = out.started ? Mat3(out.start.matrix * options.sample_noise * out.start.matrix.transpose())
                               : options.sample_noise;
    const NoiseBias b = estimate_noise_bias(options.model, y, co, out.estimate, S, options.noise_bias_seed);
    if (b.replicates > 0) {
      const Vec3 offset = out.correction.offset, gain = out.gain;
      remove_noise_bias(out.estimate, b, M);
      compose(file, out);
      out.noise_bias_replicates = b.replicates;
      out.offset_noise_bias = offset - out.correction.offset;
      out.gain_noise_bias = gain - out.gain;
    }
  }

  // The program measured, each position's residual, and the information at the estimate.
  const RowFunction row = visit_model(options.model, [](auto m) -> RowFunction { return &dynamic_row<decltype(m)>; });
  std::vector<double> J, w;
  std::vector<Eigen::VectorXd> rows;
  Eigen::MatrixXd info = Eigen::MatrixXd::Zero(P, P);
  double weighted = 0, chi = 0;
  for (const auto& p : y) {
    const Vec3 c = r.meter.compensate(p.mean());
    out.directions.push_back(c.normalized());
    J.push_back((options.modulus == Modulus::norm ? c.norm() : c.dot(*p.nominal)) / M - 1);
    w.push_back(options.weight_by_samples ? static_cast<double>(p.samples.size()) : 1.0);
    rows.push_back(row(options.modulus == Modulus::norm ? out.directions.back() : Vec3(p.nominal->normalized())));
    const Eigen::VectorXd& h = rows.back();
    info += w.back() * h * h.transpose();
    weighted += w.back() * J.back() * J.back();
    if (r.noise > 0) {
      const double z = J.back() * M * std::sqrt(static_cast<double>(p.samples.size())) / r.noise;
      chi += z * z;
    }
  }
  // With the noise bias taken off, the residuals are those of the estimate as it now stands.
  if (out.noise_bias_replicates > 0) {
    double ss = 0;
    for (double j : J) ss += j * j;
    out.estimate.residual_rms = std::sqrt(ss / n) * M;
  }
  const Eigen::MatrixXd K = info.ldlt().solve(Eigen::MatrixXd::Identity(P, P));
  out.dof = n - P;
  const double s = out.dof > 0 ? std::sqrt(weighted / out.dof) : 0;
  const Eigen::MatrixXd none;
  Eigen::MatrixXd model;
  if (r.noise_source == NoiseSource::scatter && out.dof >= kErrorModelDof) {
    std::vector<double> counts;
    for (const auto& p : y) counts.push_back(static_cast<double>(p.samples.size()));
    const BetweenPoses bp = between_poses(rows, J, counts, w, (r.noise / M) * (r.noise / M));
    model = bp.covariance;
    out.between_std = std::sqrt(bp.between) * M;
    out.within_std = r.noise;
    out.model_standardised = bp.standardised;
  }
  assign_errors(out, r.noise_source != NoiseSource::none ? Eigen::MatrixXd((r.noise / M) * (r.noise / M) * r.K) : none,
                out.dof > 0 ? Eigen::MatrixXd(s * s * K) : none, model);
  if (r.noise_source == NoiseSource::scatter && r.noise > 0 && out.dof > 0) {
    out.chi_square = chi;
    out.chi_square_p = boost::math::cdf(boost::math::complement(boost::math::chi_squared(out.dof), chi));
  }
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Eigen::VectorXd& h = rows[k];
    const double leverage = std::min(w[k] * h.dot(K * h), 1.0 - 1e-12);
    PositionResidual pr{data[k].line, J[k], 0.0};
    if (s > 0) pr.standardised = J[k] * std::sqrt(w[k]) / (s * std::sqrt(1 - leverage));
    out.residuals.push_back(pr);
  }
  return out;
}

}  // namespace scalcal
