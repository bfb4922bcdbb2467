// `calibrate`: the model the layout carries, the fit in any units, the positions' residuals, the
// warnings a bench engineer must read, and the measured program's quality (calibrate.hpp).
#include "commands/calibration/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

#include "commands/core/usage_error.hpp"
#include "numeric/calibration/model_choice.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal::commands {
namespace {

std::string number(double v, int digits = 3) {
  std::ostringstream s;
  s << std::setprecision(digits) << v;
  return s.str();
}

// What scalar calibration at one magnitude leaves out for the model, in one sentence: the rotation,
// for every model, then what the model's type says it leaves out.
std::string not_estimated_text(ModelKind model) {
  const std::string rotation =
      "the rotation part of the misalignment (three angles) leaves every modulus unchanged and is not estimated";
  const std::string_view own = model_not_estimated(model);
  return own.empty() ? rotation : rotation + "; " + std::string(own);
}

// The model: the requested one if the layout carries it (InputError naming what would work
// otherwise), or the richest the layout carries.
void choose(const CalibrateRequest& q, const std::vector<PositionSamples>& data, double magnitude,
            CalibrateResult& out) {
  const auto directions = layout_directions(data, magnitude, !q.magnitude, q.modulus);
  if (!directions)
    throw InputError(q.file, 0,
                     "no ellipsoid passes near the " + std::to_string(data.size()) +
                         " positions' means: they are too few or too flat to judge the layout");
  const Program layout{*directions};
  const bool gain = gain_estimated(data, magnitude, !q.magnitude, q.modulus);
  const auto automatic = choose_model(layout, gain);
  if (!q.model) {
    if (!automatic)
      throw InputError(q.file, 0,
                       std::to_string(data.size()) + " positions carry none of the models " +
                           models_supporting(ModelCapability::auto_choice) + " (" +
                           judge_layout(auto_choice_models().back(), layout, gain).why + ")");
    out.model = automatic->model;
    out.model_reason = automatic->reason;
    out.not_identifiable = automatic->not_identifiable;
    return;
  }
  const LayoutVerdict v = judge_layout(*q.model, layout, gain);
  if (!v.carried) {
    std::string hint = automatic
                           ? words("; {model} ") + std::string(model_name(automatic->model)) + " (or auto) would work"
                           : "; no registered model would work with these positions";
    throw InputError(q.file, 0,
                     words("{model} ") + std::string(model_name(*q.model)) +
                         " cannot be identified by these positions (" + v.why + ")" + hint);
  }
  out.model = *q.model;
  out.model_reason = words("requested ({model} ") + std::string(model_name(*q.model)) +
                     "; the layout carries it, condition " + number(v.condition) + ")";
}

void collect_positions(const CalibrationInput& in, CalibrateResult& out) {
  const AnyUnitsCalibration& a = out.fit;
  for (std::size_t k = 0; k < in.data.size(); ++k) {
    PositionResult p;
    p.line = in.data[k].line;
    p.samples = static_cast<int>(in.data[k].samples.size());
    if (in.every_sample) {
      p.start = p.end = in.log->t[static_cast<std::size_t>(in.sample_index[k])];
    } else if (in.log && k < in.detection.intervals.size()) {
      p.start = in.detection.intervals[k].start;
      p.end = in.detection.intervals[k].stop;
    }
    p.mean = in.data[k].mean();
    p.direction = a.directions[k];
    p.residual = a.residuals[k].residual * a.magnitude;
    p.standardised_residual = a.residuals[k].standardised;
    out.positions.push_back(p);
    // A tumbling log's samples beyond the cut were left out as disturbed stretches already.
    if (!in.every_sample && std::abs(p.standardised_residual) > kOutlierSigmas)
      out.outliers.push_back(static_cast<int>(k));
  }
  std::sort(out.outliers.begin(), out.outliers.end(), [&](int x, int y) {
    return std::abs(out.positions[static_cast<std::size_t>(x)].standardised_residual) >
           std::abs(out.positions[static_cast<std::size_t>(y)].standardised_residual);
  });
}

// A fit whose numbers are not all finite is never reported.
void check_finite(const CalibrateResult& r) {
  const AnyUnitsCalibration& a = r.fit;
  bool ok = a.correction.offset.allFinite() && a.correction.matrix.allFinite() && a.estimate.X.allFinite() &&
            a.scale_deviation.allFinite() && std::isfinite(a.estimate.residual_rms);
  for (const auto& p : r.positions) ok = ok && p.direction.allFinite() && std::isfinite(p.residual);
  if (!ok)
    throw InputError(r.file, 0,
                     words("the fit of {model} ") + std::string(model_name(r.model)) +
                         " gave values that are not finite (" + a.estimate.summary.message + "); nothing is reported");
}

void collect_warnings(const CalibrateResult& r, Warnings& w) {
  const AnyUnitsCalibration& a = r.fit;
  const auto& s = a.estimate.summary;
  if (!s.converged())
    w.push_back({r.file, "the fit did not converge after " + std::to_string(s.iterations) + " iterations (" +
                             s.message +
                             "): the calibration is not to be used (its file says \"converged\": false; `scalcal "
                             "correct` refuses it)"});
  if (a.estimate.noise_source == NoiseSource::none && a.dof == 0)
    w.push_back({r.file, std::to_string(a.estimate.positions) +
                             " positions with one sample each fit exactly; the noise and the standard errors cannot be "
                             "estimated"});
  else if (a.dof < 5 && a.dof > 0)
    w.push_back({r.file, "only " + std::to_string(a.dof) +
                             " degrees of freedom (positions minus parameters): the standard errors are themselves "
                             "uncertain; 95 % intervals are +- " +
                             number(r.t95, 4) + " standard errors (Student's t)"});
  if (!a.model_standardised.empty()) {
    // Under the error model (noise within poses and scatter between them), a position whose residual
    // is beyond the Bonferroni bound at 1 % over all positions is an outlier, not the model's.
    const double n = static_cast<double>(a.model_standardised.size());
    const double bound = boost::math::quantile(boost::math::complement(boost::math::normal(), 0.005 / n));
    std::vector<std::pair<double, int>> worst;
    for (std::size_t k = 0; k < a.model_standardised.size(); ++k)
      if (std::abs(a.model_standardised[k]) > bound)
        worst.emplace_back(std::abs(a.model_standardised[k]), r.positions[k].line);
    std::sort(worst.rbegin(), worst.rend());
    if (!worst.empty()) {
      std::string list;
      for (std::size_t k = 0; k < worst.size() && k < 8; ++k)
        list += std::string(k ? "," : "") + " line " + std::to_string(worst[k].second) + " (" + number(worst[k].first) +
                ")";
      w.push_back({r.file, std::to_string(worst.size()) +
                               " positions disagree beyond what the noise within poses and "
                               "the scatter between them allow (|z| > " +
                               number(bound) + ", 1 % over all positions):" + list +
                               " (mislabelled positions or outliers?)"});
    }
  } else if (a.chi_square && a.chi_square_p < 1e-3) {
    // Which positions disagree: |z| > 3 standard errors of their mean by the noise within positions.
    std::vector<std::pair<double, int>> worst;
    const double noise = a.estimate.noise / a.magnitude;
    for (const auto& p : r.positions) {
      const double z = std::abs(p.residual / a.magnitude) * std::sqrt(static_cast<double>(p.samples)) / noise;
      if (z > 3) worst.emplace_back(z, p.line);
    }
    std::sort(worst.rbegin(), worst.rend());
    std::string list;
    for (std::size_t k = 0; k < worst.size() && k < 8; ++k)
      list +=
          std::string(k ? "," : "") + " line " + std::to_string(worst[k].second) + " (" + number(worst[k].first) + ")";
    if (worst.size() > 8) list += " and " + std::to_string(worst.size() - 8) + " more";
    w.push_back({r.file, "the fit contradicts its own noise estimate: chi-square " + number(*a.chi_square, 4) +
                             " for " + std::to_string(a.dof) + " degrees of freedom (p = " + number(a.chi_square_p, 2) +
                             "), the residuals between positions " + number(std::sqrt(*a.chi_square / a.dof)) +
                             " times what the noise within positions predicts; " +
                             (worst.empty() ? std::string("no single position stands out (systematic errors the model "
                                                          "lacks?)")
                                            : "positions that disagree (first line, |residual| in standard errors):" +
                                                  list + " (mislabelled positions or outliers?)") +
                             "; the standard errors given are the residual-based ones"});
  }
  if (!r.outliers.empty()) {
    std::string list;
    for (std::size_t k = 0; k < r.outliers.size() && k < 5; ++k) {
      const auto& p = r.positions[static_cast<std::size_t>(r.outliers[k])];
      list += (k ? ", " : "") + std::string("line ") + std::to_string(p.line) + " (" +
              number(p.standardised_residual, 2) + " sigma)";
    }
    w.push_back({r.file, std::to_string(r.outliers.size()) + " positions' residuals are more than " +
                             number(kOutlierSigmas) + " times the others' scale: " + list});
  }
}

}  // namespace

ProgramQuality program_quality(const CalibrateRequest& q, CalibrateResult& r, const Progress& progress);

namespace {

// A tumbling log's fit: fit every usable sample, leave out the disturbed stretches its residuals
// show, fit again (at most five rounds); then standard errors that allow for residuals correlated
// in time (Newey-West over a second of samples) beside the noise-based ones (second differences).
void fit_every_sample(const CalibrateRequest& q, CalibrationInput& in, const AnyUnitsOptions& ao,
                      CalibrateResult& out) {
  const RawLog& log = *in.log;
  const double rate = 1 / in.detection.sample_period;
  std::vector<char> keep = in.detection.usable;
  TumblingReport t;
  for (int round = 0; round < 5; ++round) {
    in.data = sample_positions(log, keep, in.sample_index);
    out.fit = calibrate_any_units(q.file, in.data, ao);
    std::vector<double> residual;
    residual.reserve(out.fit.residuals.size());
    for (const auto& r : out.fit.residuals) residual.push_back(r.residual);
    const auto found = disturbed_stretches(log, in.sample_index, residual, std::max(1, static_cast<int>(rate / 2)));
    if (found.empty()) break;
    for (const auto& s : found) {
      for (int i = s.begin; i <= s.end; ++i) keep[static_cast<std::size_t>(i)] = 0;
      t.disturbed.push_back(s);
    }
  }
  // The final fit takes off the bias the single samples' noise gives it (noise_bias.hpp), estimated
  // with the log's second-difference noise on every axis.
  if (in.motion.noise.allFinite() && (in.motion.noise.array() > 0).all()) {
    AnyUnitsOptions debiased = ao;
    debiased.sample_noise = in.motion.noise.cwiseProduct(in.motion.noise).asDiagonal();
    out.fit = calibrate_any_units(q.file, in.data, debiased);
  }
  // Later rounds see the earlier stretches' neighbours as one run across the gap: overlapping
  // stretches are one.
  std::sort(t.disturbed.begin(), t.disturbed.end(),
            [](const DisturbedStretch& a, const DisturbedStretch& b) { return a.begin < b.begin; });
  std::vector<DisturbedStretch> merged;
  for (const auto& d : t.disturbed) {
    if (!merged.empty() && d.begin <= merged.back().end + 1) {
      DisturbedStretch& m = merged.back();
      if (d.end > m.end) m.end = d.end, m.stop = d.stop, m.last_line = d.last_line;
      m.worst = std::max(m.worst, d.worst);
    } else {
      merged.push_back(d);
    }
  }
  t.disturbed = merged;
  AnyUnitsCalibration& a = out.fit;
  const auto N = static_cast<double>(a.residuals.size());
  t.samples_used = static_cast<int>(a.residuals.size());
  // The lag: twice the time the meter takes to turn by 60 degrees (decorrelation_lag: Bartlett's
  // weights give that turn's covariance half its weight), at least a second of samples and Newey and
  // West's rule of thumb. Checked on the QMC5883L log against a moving-block bootstrap of an
  // independent fit (docs/magnetometer.md).
  t.lag = std::max({static_cast<int>(std::lround(rate)), static_cast<int>(4 * std::pow(N / 100, 2.0 / 9)),
                    2 * decorrelation_lag(a.directions)});
  std::vector<double> J;
  for (const auto& r : a.residuals) J.push_back(r.residual);
  const Eigen::MatrixXd nw = newey_west_covariance(model_rows(a.model, a.directions), J, t.lag);
  const Eigen::VectorXd independent = a.achieved_std;
  a.estimate.noise = in.motion.noise_relative * a.magnitude;
  a.estimate.noise_source = NoiseSource::differences;
  assign_errors(a, in.motion.noise_relative * in.motion.noise_relative * a.estimate.K, nw);
  t.correlation_factor = (a.achieved_std.array() / independent.array()).maxCoeff();
  t.noise = a.estimate.noise;
  t.coverage = sphere_coverage(a.directions);
  out.tumbling = t;
}

void fit_model(const CalibrateRequest& q, CalibrationInput& in, AnyUnitsOptions ao, CalibrateResult& out) {
  ao.model = out.model;
  if (in.every_sample)
    fit_every_sample(q, in, ao, out);
  else
    out.fit = calibrate_any_units(q.file, in.data, ao);
}

// Whether the fit estimated the field's gain with the offsets (judge_layout's gain_estimated).
bool gain_fitted(const CalibrateRequest& q, const CalibrateResult& out) { return !q.magnitude || out.fit.started; }

// --model auto judged the layout at its starting ellipsoid's directions; after the fit it is judged
// again at the fitted ones. A model that is not identified there, or that did not converge where a
// simpler model's fitted directions show the positions cannot carry it, gives way to the richest
// simpler model that converges and is carried, with a warning saying so. A model that did not
// converge although the positions do carry it (the simpler fit's directions say so) stays, not
// converged: the data are at fault (a mislabelled position), and no simpler model would be right.
void fit_with_fallback(const CalibrateRequest& q, CalibrationInput& in, const AnyUnitsOptions& ao,
                       CalibrateResult& out) {
  fit_model(q, in, ao, out);
  const auto trouble = [&]() -> std::string {
    if (!out.fit.estimate.summary.converged()) return "did not converge (" + out.fit.estimate.summary.message + ")";
    const LayoutVerdict v = judge_layout(out.model, Program{out.fit.directions}, gain_fitted(q, out));
    return v.carried ? "" : "is not identified at the fitted directions (" + v.why + ")";
  };
  const std::string why = trouble();
  if (why.empty() || q.model) {
    // An explicit model is the user's: one that did not converge is reported as such (exit 1).
    if (!why.empty() && out.fit.estimate.summary.converged())
      out.warnings.push_back({q.file, words("{model} ") + std::string(model_name(out.model)) + " " + why});
    return;
  }
  const ModelKind first = out.model;
  const CalibrationInput first_in = in;
  const CalibrateResult first_out = out;
  bool below = false;
  for (const ModelKind simpler : auto_choice_models()) {  // richest first: those after `first`
    below = below || simpler == first;
    if (!below || simpler == first) continue;
    const std::string name(model_name(simpler));
    out.model = simpler;
    try {
      fit_model(q, in, ao, out);
    } catch (const InputError&) {
      continue;
    }
    if (!trouble().empty()) continue;
    if (judge_layout(first, Program{out.fit.directions}, gain_fitted(q, out)).carried)
      break;  // the data, not the layout
    const std::string note = "model " + std::string(model_name(first)) + " (auto) " + why + "; the simpler " + name +
                             " converges and the fitted directions cannot carry " + std::string(model_name(first));
    out.warnings.push_back({q.file, note + ": " + name + " is the one reported"});
    out.model_reason = "auto: " + note;
    return;
  }
  in = first_in;
  out = first_out;
}

// The calibration's units: as given (--units), or where the data and the Earth fix them.
void resolve_units(const CalibrateRequest& q, CalibrateResult& out) {
  CalibrationUnits& u = out.units;
  const bool magnitude_auto = !q.magnitude;
  u.unit_modulus = magnitude_auto;
  u.field_strength = out.field_strength;
  if (!q.raw_units.empty()) {
    out.raw_counts = is_count_unit(q.raw_units);
    if (!out.raw_counts) u.raw = parse_unit(q.raw_units);
  }
  if (!q.physical_units.empty()) {
    u.physical = parse_unit(q.physical_units);
    out.units_reason = words("given ({units})");
  } else if (!magnitude_auto && out.instrument) {
    u.physical = unit_of_earth_magnitude(*out.instrument, *q.magnitude);
    if (u.physical)
      out.units_reason = "physical units " + std::string(u.physical->name) + words(" from {magnitude} ") +
                         magnitude_text(q.magnitude) + " (the Earth's " +
                         (*out.instrument == Instrument::accel ? "gravity" : "field") + " in those units)";
  }
  if (!u.raw && !out.raw_counts && !out.fit.started && u.physical) {
    u.raw = u.physical;
    out.units_reason += std::string(out.units_reason.empty() ? "" : "; ") +
                        words("raw units the physical ones (the data were within 10 % of {magnitude})");
  }
  if (magnitude_auto)
    out.units_reason = std::string(out.units_reason.empty() ? "" : out.units_reason + "; ") +
                       words("corrected to unit modulus ({magnitude auto})");
}

// A thermal fit corrects in the log's own units (|I| = --magnitude in them): raw and physical units are one,
// as --units U,U says or as the Earth's magnitude in a unit and --instrument fix it.
void thermal_units(const CalibrateRequest& q, double magnitude, CalibrateResult& r) {
  r.instrument = q.instrument;
  if (q.instrument == Instrument::gyro)
    throw UsageError(
        words("calibrate: a thermal model is an accelerometer's or a magnetometer's ({instrument accel|mag})"));
  if (!q.raw_units.empty()) {
    if (q.raw_units != q.physical_units || is_count_unit(q.raw_units))
      throw UsageError(
          words("calibrate: {units}: a thermal fit corrects in the log's own units (|I| = {magnitude} in them): "
                "give one unit twice, such as m/s^2,m/s^2, not ") +
          q.raw_units + "," + q.physical_units);
    r.units.raw = r.units.physical = parse_unit(q.raw_units);
    r.units_reason = words("given ({units})");
  } else if (q.instrument) {
    r.units.raw = r.units.physical = unit_of_earth_magnitude(*q.instrument, magnitude);
    if (r.units.raw)
      r.units_reason = "raw and physical units " + std::string(r.units.raw->name) + words(" from {magnitude} ") +
                       magnitude_text(q.magnitude) + " (the Earth's " +
                       (*q.instrument == Instrument::accel ? "gravity" : "field") + " in those units)";
  }
}

}  // namespace

CalibrateResult calibrate(const CalibrateRequest& q, CalibrationInput in, const Progress& progress) {
  check_calibrate_request(q);
  CalibrateResult out;
  out.file = q.file;
  out.request = q;
  out.warnings = q.warnings;
  out.warnings.insert(out.warnings.end(), in.warnings.begin(), in.warnings.end());
  out.instrument = in.instrument;
  out.instrument_reason = in.instrument_reason;
  const bool magnitude_auto = !q.magnitude;
  const double magnitude = q.magnitude.value_or(1.0);
  out.weight_by_samples = q.weights ? *q.weights == PositionWeights::samples : !in.log;
  if (!q.keep_outliers && !in.every_sample) out.excluded = exclude_outlier_samples(in.data);
  if (!out.excluded.empty()) out.warnings.push_back({q.file, outlier_warning(out.excluded)});
  if (progress) progress("model", 0, 3);
  choose(q, in.data, magnitude, out);
  if (!q.model && !is_default_model(out.model))
    out.warnings.push_back({q.file, "model " + std::string(model_name(out.model)) + " (auto): " + out.model_reason});
  if (magnitude_auto)
    out.not_identifiable.emplace_back(
        "the field's strength and the mean scale factor: one unknown, so the correction "
        "maps to unit modulus and the scale deviations are relative to their geometric "
        "mean");
  AnyUnitsOptions ao;
  ao.modulus = q.modulus;
  ao.magnitude = magnitude;
  ao.magnitude_auto = magnitude_auto;
  ao.weight_by_samples = out.weight_by_samples;
  if (progress) progress("fit", 1, 3);
  fit_with_fallback(q, in, ao, out);
  out.not_estimated = not_estimated_text(out.model);
  if (magnitude_auto) {
    out.field_strength = out.fit.nominal_gain;
    out.field_strength_std = out.fit.nominal_gain_std;
  }
  resolve_units(q, out);
  if (out.fit.dof >= 1) out.t95 = boost::math::quantile(boost::math::students_t(out.fit.dof), 0.975);
  if (in.log) {
    out.detection = in.detection;
    out.chosen = in.chosen;
    out.rows = in.log->size();
    out.chunk_rows = q.chunk_rows;
    out.chunks = q.chunk_rows > 0 ? in.chunks : 0;
    out.motion = in.motion;
    // The median time step's reciprocal, to 12 digits (a log's time stamps carry no more).
    out.sample_rate = std::stod(number(1 / in.detection.sample_period, 12));
  }
  collect_positions(in, out);
  check_finite(out);
  collect_warnings(out, out.warnings);
  if (progress) progress("program", 2, 3);
  out.program = program_quality(q, out, progress);
  return out;
}

CalibrateResult calibrate(const CalibrateRequest& q, const Progress& progress) {
  if (q.thermal) {
    if (!q.magnitude)
      throw UsageError(
          words("calibrate: a thermal model needs {magnitude M}, the field's modulus in the log's units (not auto)"));
    CalibrateResult r;
    r.file = q.file;
    r.request = q;
    const CsvTable table = q.table ? *q.table : read_csv(q.file);
    r.thermal = std::make_shared<ThermalCalibration>(
        calibrate_thermal(q.file, table, *q.thermal, q.temperature, *q.magnitude, q.intervals));
    r.warnings = r.thermal->warnings;
    thermal_units(q, *q.magnitude, r);
    return r;
  }
  check_calibrate_request(q);
  return calibrate(q, read_calibration_input(q), progress);
}

}  // namespace scalcal::commands
