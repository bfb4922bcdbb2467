// `calibrate`: the model the layout carries, the fit in any units, the positions' residuals, the
// warnings a bench engineer must read, and the measured program's quality (calibrate.hpp).
#include "commands/calibrate.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include <boost/math/distributions/students_t.hpp>

#include "commands/usage_error.hpp"
#include "numeric/calibration/model_choice.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::commands {
namespace {

std::string number(double v, int digits = 3) {
  std::ostringstream s;
  s << std::setprecision(digits) << v;
  return s.str();
}

// What scalar calibration at one magnitude leaves out for the model, in one sentence.
std::string not_estimated_text(ModelKind model) {
  const std::string rotation =
      "the rotation part of the misalignment (three angles) leaves every modulus unchanged and is not estimated";
  const std::string_view name = model_name(model);
  if (name == "bias3")
    return rotation +
           "; the scale factors are taken as equal (one gain, from the start) and the axes as orthogonal: "
           "their errors go into the residual";
  if (name == "axis6") return rotation + "; the axes are taken as orthogonal: non-orthogonality goes into the residual";
  if (name == "cubic12")
    return rotation +
           "; at one magnitude the cubic term is identified as c_i |I| only (it cannot be told from a scale factor "
           "that depends on the magnitude), and never from positions along the axes alone, where x^3 = x makes it "
           "the bias";
  return rotation;
}

// The model: the requested one if the layout carries it (InputError naming what would work
// otherwise), or the richest the layout carries.
void choose(const CalibrateRequest& q, const std::vector<PositionSamples>& data, double magnitude,
            CalibrateResult& out) {
  const auto directions = layout_directions(data, magnitude, q.magnitude == "auto", q.modulus);
  if (!directions)
    throw InputError(q.file, 0,
                     "no ellipsoid passes near the " + std::to_string(data.size()) +
                         " positions' means: they are too few or too flat to judge the layout");
  const Program layout{*directions};
  const auto automatic = choose_model(layout);
  if (!q.model) {
    if (!automatic)
      throw InputError(q.file, 0,
                       std::to_string(data.size()) + " positions carry none of the models paper9, axis6, bias3 (" +
                           judge_layout(*parse_model("bias3"), layout).why + ")");
    out.model = automatic->model;
    out.model_reason = automatic->reason;
    out.not_identifiable = automatic->not_identifiable;
    return;
  }
  const LayoutVerdict v = judge_layout(*q.model, layout);
  if (!v.carried) {
    std::string hint = automatic ? "; --model " + std::string(model_name(automatic->model)) + " (or auto) would work"
                                 : "; no registered model would work with these positions";
    throw InputError(q.file, 0,
                     "--model " + std::string(model_name(*q.model)) + " cannot be identified by these positions (" +
                         v.why + ")" + hint);
  }
  out.model = *q.model;
  out.model_reason = "requested (--model " + std::string(model_name(*q.model)) + "; the layout carries it, condition " +
                     number(v.condition) + ")";
}

void collect_positions(const CalibrationInput& in, CalibrateResult& out) {
  const AnyUnitsCalibration& a = out.fit;
  for (std::size_t k = 0; k < in.data.size(); ++k) {
    PositionResult p;
    p.line = in.data[k].line;
    p.samples = static_cast<int>(in.data[k].samples.size());
    if (in.log && k < in.detection.intervals.size()) {
      p.start = in.detection.intervals[k].start;
      p.end = in.detection.intervals[k].stop;
    }
    p.mean = in.data[k].mean();
    p.direction = a.directions[k];
    p.residual = a.residuals[k].residual * a.magnitude;
    p.standardised_residual = a.residuals[k].standardised;
    out.positions.push_back(p);
    if (std::abs(p.standardised_residual) > kOutlierSigmas) out.outliers.push_back(static_cast<int>(k));
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
                     "the fit of --model " + std::string(model_name(r.model)) + " gave values that are not finite (" +
                         a.estimate.summary.message + "); nothing is reported");
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
  if (a.chi_square && a.chi_square_p < 1e-3) {
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

CalibrateResult calibrate(const CalibrateRequest& q, CalibrationInput in, const Progress& progress) {
  check_calibrate_request(q);
  CalibrateResult out;
  out.file = q.file;
  out.request = q;
  out.warnings = q.warnings;
  out.warnings.insert(out.warnings.end(), in.warnings.begin(), in.warnings.end());
  const bool magnitude_auto = q.magnitude == "auto";
  const double magnitude = magnitude_auto ? 1.0 : std::stod(q.magnitude);
  out.weight_by_samples = q.weights == "samples" || (q.weights == "auto" && !in.log);
  if (!q.keep_outliers) out.excluded = exclude_outlier_samples(in.data);
  if (!out.excluded.empty()) out.warnings.push_back({q.file, outlier_warning(out.excluded)});
  if (progress) progress("model", 0, 3);
  choose(q, in.data, magnitude, out);
  if (!q.model && out.model != ModelKind::paper9)
    out.warnings.push_back({q.file, "model " + std::string(model_name(out.model)) + " (auto): " + out.model_reason});
  out.not_estimated = not_estimated_text(out.model);
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
  ao.model = out.model;
  if (progress) progress("fit", 1, 3);
  out.fit = calibrate_any_units(q.file, in.data, ao);
  if (magnitude_auto) {
    out.field_strength = out.fit.nominal_gain;
    out.field_strength_std = out.fit.nominal_gain_std;
  }
  if (out.fit.dof >= 1) out.t95 = boost::math::quantile(boost::math::students_t(out.fit.dof), 0.975);
  if (in.log) {
    out.detection = in.detection;
    out.rows = in.log->size();
  }
  collect_positions(in, out);
  check_finite(out);
  collect_warnings(out, out.warnings);
  if (progress) progress("program", 2, 3);
  out.program = program_quality(q, out, progress);
  return out;
}

CalibrateResult calibrate(const CalibrateRequest& q, const Progress& progress) {
  check_calibrate_request(q);
  return calibrate(q, read_calibration_input(q), progress);
}

}  // namespace scalcal::commands
