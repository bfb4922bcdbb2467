#include "experiments/cli/calibration_report.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

#include "commands/evaluation_json.hpp"
#include "experiments/cli/calibrate_model.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/cli/region_option.hpp"
#include "numeric/calibration/any_units.hpp"
#include "numeric/calibration/goodness_of_fit.hpp"
#include "numeric/calibration/outlier_samples.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/measurements_csv.hpp"
#include "numeric/region/program_advice.hpp"

namespace scalcal::cli {
namespace {

constexpr double kOutlierSigmas = 5;  // a position's standardised residual above this is flagged

const char* kParameterNames[9] = {"bias_x",  "bias_y",     "bias_z",     "scale_x",   "scale_y",
                                  "scale_z", "nonorth_xy", "nonorth_yz", "nonorth_zx"};

Json triple(const Vec3& v) { return Json{v(0), v(1), v(2)}; }
Json triple_or_null(const Vec3& v, bool ok) { return ok ? triple(v) : Json(); }
Json rows_of(const Mat3& m) { return Json{triple(m.row(0)), triple(m.row(1)), triple(m.row(2))}; }

std::string lines_text(const std::vector<int>& lines, int total) {
  std::string s;
  for (int l : lines) s += (s.empty() ? "" : ", ") + std::to_string(l);
  return s + (total > static_cast<int>(lines.size()) ? ", ..." : "");
}

}  // namespace

std::string magnitude_problem(const std::string& s) {
  if (s == "auto") return "";
  try {
    std::size_t used = 0;
    const double v = std::stod(s, &used);
    if (used == s.size() && std::isfinite(v) && v > 0) return "";
  } catch (...) {
  }
  return "must be a positive number or auto, got '" + s + "'";
}

void check_calibration_request(const CalibrationRequest& o) {
  if (const std::string problem = magnitude_problem(o.magnitude); !problem.empty())
    throw UsageError("calibrate: --magnitude " + problem);
  if (o.model != ModelKind::paper9 && o.magnitude == "auto")
    throw UsageError("calibrate: --magnitude auto works with the paper9 model only: for --model " +
                     std::string(model_name(o.model)) +
                     " the field's strength would be one more unknown (with the mean scale factor for axis6 and "
                     "cubic12, with nothing to fix the gain for bias3); give |I|");
  if (o.model != ModelKind::paper9 && !o.regions.empty())
    throw UsageError("calibrate: --region (the advice on what to add) works with the paper9 model only");
}

CalibrationInput read_calibration_input(const CalibrationRequest& o) {
  const bool need_nominal = o.modulus == Modulus::projection;
  const std::string text = read_text_file(o.file);
  if (o.format == "text" || (o.format == "auto" && looks_like_text_log(text)))
    return calibration_input(parse_raw_log(text, o.file, LogFormat::text), o);
  TableFormat lenient;  // a raw log's dropouts are counted, not refused
  lenient.nonfinite_allowed = true;
  const CsvTable table = parse_table(text, o.file, lenient);
  if (is_raw_log(table)) return calibration_input(raw_log_from_table(table), o);
  CalibrationInput in;
  in.data = measurements_from_table(parse_csv(text, o.file), need_nominal);  // strict, as always
  return in;
}

CalibrationInput calibration_input(RawLog log, const CalibrationRequest& o) {
  const int parameters = model_parameters(o.model);
  CalibrationInput in;
  in.log = std::move(log);
  if (o.modulus == Modulus::projection)
    throw InputError(o.file, 0, "a raw log has no nominal directions: the projection modulus needs them");
  in.detection = detect_static_intervals(*in.log, o.intervals);
  const auto& d = in.detection;
  if (d.nonfinite > 0)
    std::cerr << "scalcal calibrate: " << o.file << ": warning: " << d.nonfinite
              << " rows with a NaN or infinite value are not used (lines " << lines_text(d.nonfinite_lines, d.nonfinite)
              << ")\n";
  if (d.saturated > 0)
    std::cerr << "scalcal calibrate: " << o.file << ": warning: " << d.saturated
              << " samples sit at an output's extreme in runs of three or more (saturated) and are not used (lines "
              << lines_text(d.saturated_lines, d.saturated) << ")\n";
  if (d.intervals.size() < static_cast<std::size_t>(parameters)) {
    std::ostringstream s;
    s << "found " << d.intervals.size() << " static intervals; scalar calibration needs at least " << parameters
      << " positions. A window of " << d.window << " samples is static when its variance norm stays below "
      << d.threshold << " = --threshold-factor " << o.intervals.threshold_factor << " x " << d.still_variance
      << " (the first " << o.intervals.still_seconds << " s), for at least --min-interval " << o.intervals.min_seconds
      << " s. Is the log's start still? A larger --threshold-factor or a shorter --min-interval finds more";
    throw InputError(o.file, 0, s.str());
  }
  for (const auto& iv : d.intervals) {
    PositionSamples p;
    p.line = in.log->lines[static_cast<std::size_t>(iv.begin)];
    for (int i = iv.begin; i <= iv.end; ++i) {
      p.samples.push_back(in.log->samples[static_cast<std::size_t>(i)]);
      p.sample_lines.push_back(in.log->lines[static_cast<std::size_t>(i)]);
    }
    in.data.push_back(std::move(p));
  }
  return in;
}

Report calibrate_report(const CalibrationRequest& o, CalibrationInput in) {
  check_calibration_request(o);
  const Modulus modulus = o.modulus;
  AnyUnitsOptions ao;
  ao.modulus = modulus;
  ao.magnitude_auto = o.magnitude == "auto";
  ao.magnitude = ao.magnitude_auto ? 1.0 : std::stod(o.magnitude);
  const Region region = resolve_region(o.regions, "calibrate");
  const CriterionKind criterion = o.criterion;
  const ModelKind model = o.model;
  ao.weight_by_samples = o.weights == "samples" || (o.weights == "auto" && !in.log);
  std::vector<ExcludedSample> excluded;
  if (!o.keep_outliers) excluded = exclude_outlier_samples(in.data);
  if (!excluded.empty())
    std::cerr << "scalcal calibrate: " << o.file << ": warning: " << outlier_warning(excluded) << "\n";
  if (model != ModelKind::paper9) {
    ModelCalibrationRequest q;
    q.file = o.file;
    q.out = o.out;
    q.model = model;
    q.modulus = modulus;
    q.magnitude = ao.magnitude;
    q.weight_by_samples = ao.weight_by_samples;
    return model_calibration_report(q, in.data);
  }
  const AnyUnitsCalibration a = calibrate_any_units(o.file, in.data, ao);
  const CalibrationResult& r = a.estimate;
  const bool have_std = r.noise_source != NoiseSource::none;
  if (!have_std)
    std::cerr << "scalcal calibrate: " << o.file << ": warning: 9 positions with one sample each fit exactly; "
              << "the noise and the standard errors cannot be estimated\n";
  if (!r.converged)
    std::cerr << "scalcal calibrate: " << o.file << ": warning: the iteration did not converge after " << r.iterations
              << " iterations (errors too large for the linearised model?)\n";
  // The goodness of fit is the estimator's: on the data it saw (start-corrected).
  std::vector<PositionSamples> seen = in.data;
  if (a.started)
    for (auto& p : seen)
      for (auto& s : p.samples) s = a.start.apply(s);
  const auto fit = goodness_of_fit(seen, r, modulus, a.magnitude);
  if (fit && fit->p < kFitRejectP)
    std::cerr << "scalcal calibrate: " << o.file << ": warning: " << fit_warning(*fit) << "\n";
  std::vector<const PositionResidual*> outliers;
  for (const auto& p : a.residuals)
    if (std::abs(p.standardised) > kOutlierSigmas) outliers.push_back(&p);
  std::sort(outliers.begin(), outliers.end(),
            [](auto* x, auto* y) { return std::abs(x->standardised) > std::abs(y->standardised); });
  if (!outliers.empty()) {
    std::string list;
    for (std::size_t k = 0; k < outliers.size() && k < 5; ++k)
      list += (k ? ", " : "") + std::string("line ") + std::to_string(outliers[k]->line) + " (" +
              std::to_string(static_cast<int>(std::round(outliers[k]->standardised))) + " sigma)";
    std::cerr << "scalcal calibrate: " << o.file << ": warning: " << outliers.size()
              << " positions' residuals are more than 5 times the others' scale: " << list << "\n";
  }
  const ProgramAdvice advice = advise_program(Program{a.directions}, region, criterion, o.suggest);

  // The JSON object: today's keys first, then the full correction, the intervals, the program.
  Json j{{"bias", triple(a.correction.offset)},
         {"scale_deviation", triple(a.scale_deviation)},
         {"nonorthogonality", triple(a.correction.nonorthogonality)},
         {"bias_std", triple_or_null(a.bias_std, have_std)},
         {"scale_deviation_std", triple_or_null(a.scale_deviation_std, have_std)},
         {"nonorthogonality_std", triple_or_null(a.nonorthogonality_std, have_std)},
         {"iterations", r.iterations},
         {"residual_rms", r.residual_rms},
         {"positions", r.positions},
         {"samples", r.samples},
         {"modulus", modulus == Modulus::norm ? "norm" : "projection"},
         {"converged", r.converged},
         {"noise", have_std ? Json(r.noise) : Json()},
         {"chi_square", fit ? Json(fit->chi_square) : Json()},
         {"chi_square_dof", fit ? Json(fit->dof) : Json()},
         {"chi_square_p", fit ? Json(fit->p) : Json()},
         {"noise_source", r.noise_source == NoiseSource::scatter     ? "scatter"
                          : r.noise_source == NoiseSource::residuals ? "residuals"
                                                                     : "none"}};
  Json lines = Json::array();
  for (const auto& e : excluded) lines.push_back(e.line);
  j["excluded_samples"] = lines;
  j["offset"] = triple(a.correction.offset);
  j["matrix"] = rows_of(a.correction.matrix);
  j["scale"] = triple(a.correction.scale);
  j["nominal_gain"] = a.nominal_gain;
  j["magnitude"] = ao.magnitude_auto ? Json("auto") : Json(ao.magnitude);
  j["start"] = a.started ? "ellipsoid" : "none";
  j["weights"] = ao.weight_by_samples ? "samples" : "positions";
  if (ao.magnitude_auto)
    j["not_identifiable"] =
        "the field's strength and the mean scale factor: one unknown, so the correction maps to "
        "unit modulus and the scale deviations are relative to their geometric mean";
  Json predicted = Json::object(), achieved = Json::object();
  for (int k = 0; k < 9; ++k) {
    const double sk = std::sqrt(r.K(k, k)) / a.magnitude;
    predicted[kParameterNames[k]] = have_std ? Json(r.noise * sk) : Json();
    achieved[kParameterNames[k]] = a.have_achieved ? Json(a.achieved_std(k)) : Json();
  }
  j["predicted_std"] = predicted;  // in the estimator's frame: bias over the magnitude, scale, gamma
  j["achieved_std"] = achieved;
  if (in.log) {
    Json intervals = Json::array();
    for (const auto& iv : in.detection.intervals)
      intervals.push_back(Json{{"start", iv.start}, {"end", iv.stop}, {"samples", iv.samples()}});
    j["intervals"] = intervals;
    j["rows"] = in.log->size();
    j["nonfinite_rows"] = in.detection.nonfinite;
    j["saturated_samples"] = in.detection.saturated;
    j["static_threshold"] = in.detection.threshold;
  }
  const Evaluation& ev = advice.evaluation;
  Json eff = Json::object();
  for (auto c : kCriteria) eff[std::string(criterion_name(c))] = advice.efficiency[static_cast<std::size_t>(c.index())];
  const auto errors_json = [](const std::array<double, 3>& e) {
    return Json{{"bias", e[0]}, {"scale", e[1]}, {"nonorth", e[2]}};
  };
  Json measured{{"positions", ev.positions}, {"rank", ev.rank}, {"condition", ev.condition}};
  commands::add_criteria(measured, erase_model(ev));
  measured["errors"] = errors_json(rms_errors(ev));
  measured["region"] = region.text();
  measured["efficiency"] = eff;
  j["program"] = measured;
  Json out_list = Json::array();
  for (const auto* p : outliers)
    out_list.push_back(Json{{"line", p->line}, {"residual", p->residual}, {"standardised", p->standardised}});
  j["outliers"] = out_list;
  Json suggested = Json::array();
  for (const auto& s : advice.suggested)
    suggested.push_back(Json{{"position", triple(s.position)},
                             {std::string(criterion_name(criterion)), s.value},
                             {"errors", errors_json(s.errors)}});
  j["suggested"] = suggested;
  if (!o.out.empty()) write_output_file(o.out, [&](std::ostream& f) { write_json(f, j); });

  std::ostringstream text;
  text << "scalar calibration of " << o.file << " (modulus " << (modulus == Modulus::norm ? "norm" : "projection")
       << ", |I| = " << o.magnitude << ")\n";
  if (in.log)
    text << in.detection.intervals.size() << " static intervals in " << in.log->size() << " rows (window "
         << in.detection.window << " samples, threshold " << std::setprecision(4) << in.detection.threshold << ")\n";
  text << r.positions << " positions, " << r.samples << " samples, " << r.iterations << " iterations"
       << (r.converged ? "" : " (not converged)") << (a.started ? ", from an ellipsoid start" : "") << "\n";
  text << std::setprecision(6);
  const Vec3 b = a.correction.offset;
  for (int k = 0; k < 9; ++k) {
    const double v = k < 3 ? b(k) : k < 6 ? a.scale_deviation(k - 3) : a.correction.nonorthogonality(k - 6);
    const double s = k < 3 ? a.bias_std(k) : k < 6 ? a.scale_deviation_std(k - 3) : a.nonorthogonality_std(k - 6);
    text << "  " << std::left << std::setw(11) << kParameterNames[k] << std::right << std::setw(14) << v;
    if (have_std) text << "  +- " << s;
    text << (k < 3 ? "  (file units)" : k < 6 ? "" : "  rad") << "\n";
  }
  if (a.started) {
    text << "physical = matrix (raw - offset), nominal gain " << a.nominal_gain << " file units per unit:\n";
    for (int i = 0; i < 3; ++i)
      text << "  " << std::setw(14) << a.correction.matrix(i, 0) << std::setw(14) << a.correction.matrix(i, 1)
           << std::setw(14) << a.correction.matrix(i, 2) << "\n";
  }
  text << "residual rms " << r.residual_rms << ", noise " << (have_std ? std::to_string(r.noise) : "n/a") << " ("
       << (r.noise_source == NoiseSource::scatter     ? "scatter of samples within positions"
           : r.noise_source == NoiseSource::residuals ? "residuals, N - 9 degrees of freedom"
                                                      : "not estimable")
       << ")\n";
  text << "program measured: N = " << ev.positions;
  for (auto c : kCriteria) text << (c.index() ? ", " : ", ") << criterion_name(c) << " " << ev.value(c);
  text << ", thetas " << ev.theta_bias << " " << ev.theta_scale << " " << ev.theta_nonorth << ", condition "
       << ev.condition << "; efficiency on " << region.text() << ":";
  for (auto c : kCriteria)
    text << " " << criterion_name(c) << " " << advice.efficiency[static_cast<std::size_t>(c.index())];
  text << "\n";
  const auto now = rms_errors(ev);
  text << "RMS errors per unit noise (bias, scale, nonorth): " << now[0] << " " << now[1] << " " << now[2] << "\n";
  for (const auto& s : advice.suggested)
    text << "  add " << std::setprecision(4) << s.position(0) << ", " << s.position(1) << ", " << s.position(2) << ": "
         << criterion_name(criterion) << " " << std::setprecision(6) << s.value << ", RMS errors " << s.errors[0] << " "
         << s.errors[1] << " " << s.errors[2] << "\n";
  return Report{j, text.str(), r.converged ? 0 : 1};
}

}  // namespace scalcal::cli
