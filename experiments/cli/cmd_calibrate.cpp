// `scalcal calibrate --measurements FILE --magnitude M|auto [...]`: the scalar calibration of one
// meter from bench data (samples grouped by position) or from a raw log (time and raw outputs, the
// static intervals found in it), in any units, with the quality of the program measured and the
// positions worth adding (numeric/calibration/any_units.hpp, numeric/region/program_advice.hpp).
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <vector>

#include "experiments/cli/calibrate_model.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/calibration/any_units.hpp"
#include "numeric/calibration/goodness_of_fit.hpp"
#include "numeric/calibration/outlier_samples.hpp"
#include "numeric/calibration/static_intervals.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/measurements_csv.hpp"
#include "numeric/io/raw_log.hpp"
#include "numeric/region/program_advice.hpp"

namespace scalcal::cli {
namespace {

constexpr const char* kUsage =
    "calibrate --measurements FILE --magnitude M|auto [--modulus norm|projection] [--format auto|csv|text] "
    "[--still S] [--window W] [--threshold-factor K] [--min-interval T] [--weights auto|samples|positions] "
    "[--keep-outliers] [--suggest K] "
    "[--criterion C] [--region SPEC]... [--model NAME] [--out FILE] [--json]";
constexpr double kOutlierSigmas = 5;  // a position's standardised residual above this is flagged

const char* kParameterNames[9] = {"bias_x", "bias_y", "bias_z", "scale_x", "scale_y", "scale_z",
                                  "nonorth_xy", "nonorth_yz", "nonorth_zx"};

Json triple(const Vec3& v) { return Json{v(0), v(1), v(2)}; }
Json triple_or_null(const Vec3& v, bool ok) { return ok ? triple(v) : Json(); }
Json rows_of(const Mat3& m) { return Json{triple(m.row(0)), triple(m.row(1)), triple(m.row(2))}; }

std::string lines_text(const std::vector<int>& lines, int total) {
  std::string s;
  for (int l : lines) s += (s.empty() ? "" : ", ") + std::to_string(l);
  return s + (total > static_cast<int>(lines.size()) ? ", ..." : "");
}

struct Options {
  std::string file, modulus = "norm", magnitude, format = "auto", criterion = "D", out, weights = "auto",
              model = "paper9";
  std::vector<std::string> regions;
  StaticIntervalOptions intervals;
  int suggest = 3;
  bool json = false, keep_outliers = false;
};

// What the measurements file held: positions, and for a raw log how they were found.
struct Input {
  std::vector<PositionSamples> data;
  std::optional<RawLog> log;
  IntervalDetection detection;
};

Input read_input(const Options& o, bool need_nominal, int parameters) {
  Input in;
  const std::string text = read_text_file(o.file);
  if (o.format == "text" || (o.format == "auto" && looks_like_text_log(text))) {
    in.log = parse_raw_log(text, o.file, LogFormat::text);
  } else {
    TableFormat lenient;  // a raw log's dropouts are counted, not refused
    lenient.nonfinite_allowed = true;
    const CsvTable table = parse_table(text, o.file, lenient);
    if (!is_raw_log(table)) {
      in.data = measurements_from_table(parse_csv(text, o.file), need_nominal);  // strict, as always
      return in;
    }
    in.log = raw_log_from_table(table);
  }
  if (need_nominal) throw InputError(o.file, 0, "a raw log has no nominal directions: the projection modulus needs them");
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

int run(const Options& o) {
  const Modulus modulus = o.modulus == "norm" ? Modulus::norm : Modulus::projection;
  AnyUnitsOptions ao;
  ao.modulus = modulus;
  ao.magnitude_auto = o.magnitude == "auto";
  ao.magnitude = ao.magnitude_auto ? 1.0 : std::stod(o.magnitude);
  const Region region = resolve_region(o.regions, "calibrate");
  const CriterionKind criterion = criterion_of(o.criterion);
  const ModelKind model = model_of(o.model);
  if (model != ModelKind::paper9 && ao.magnitude_auto)
    throw UsageError("calibrate: --magnitude auto works with the paper9 model only: for --model " + o.model +
                     " the field's strength would be one more unknown (with the mean scale factor for axis6 and "
                     "cubic12, with nothing to fix the gain for bias3); give |I|");
  if (model != ModelKind::paper9 && !o.regions.empty())
    throw UsageError("calibrate: --region (the advice on what to add) works with the paper9 model only");

  Input in = read_input(o, modulus == Modulus::projection, model_parameters(model));
  ao.weight_by_samples = o.weights == "samples" || (o.weights == "auto" && !in.log);
  std::vector<ExcludedSample> excluded;
  if (!o.keep_outliers) excluded = exclude_outlier_samples(in.data);
  if (!excluded.empty()) std::cerr << "scalcal calibrate: " << o.file << ": warning: " << outlier_warning(excluded) << "\n";
  if (model != ModelKind::paper9) {
    ModelCalibrationRequest q;
    q.file = o.file;
    q.out = o.out;
    q.model = model;
    q.modulus = modulus;
    q.magnitude = ao.magnitude;
    q.weight_by_samples = ao.weight_by_samples;
    q.json = o.json;
    return calibrate_with_model(q, in.data);
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
  if (fit && fit->p < kFitRejectP) std::cerr << "scalcal calibrate: " << o.file << ": warning: " << fit_warning(*fit) << "\n";
  std::vector<const PositionResidual*> outliers;
  for (const auto& p : a.residuals)
    if (std::abs(p.standardised) > kOutlierSigmas) outliers.push_back(&p);
  std::sort(outliers.begin(), outliers.end(), [](auto* x, auto* y) { return std::abs(x->standardised) > std::abs(y->standardised); });
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
    j["not_identifiable"] = "the field's strength and the mean scale factor: one unknown, so the correction maps to "
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
  const auto errors_json = [](const std::array<double, 3>& e) { return Json{{"bias", e[0]}, {"scale", e[1]}, {"nonorth", e[2]}}; };
  j["program"] = Json{{"positions", ev.positions}, {"rank", ev.rank},   {"condition", ev.condition},
                      {"D", ev.D},                 {"A", ev.A},         {"E", ev.E},
                      {"S", ev.S},                 {"theta_bias", ev.theta_bias}, {"theta_scale", ev.theta_scale},
                      {"theta_nonorth", ev.theta_nonorth}, {"errors", errors_json(rms_errors(ev))},
                      {"region", region.text()}, {"efficiency", eff}};
  Json out_list = Json::array();
  for (const auto* p : outliers)
    out_list.push_back(Json{{"line", p->line}, {"residual", p->residual}, {"standardised", p->standardised}});
  j["outliers"] = out_list;
  Json suggested = Json::array();
  for (const auto& s : advice.suggested)
    suggested.push_back(Json{{"position", triple(s.position)}, {std::string(criterion_name(criterion)), s.value},
                             {"errors", errors_json(s.errors)}});
  j["suggested"] = suggested;
  if (!o.out.empty()) write_output_file(o.out, [&](std::ostream& f) { write_json(f, j); });

  if (o.json) {
    print_json(j);
    return r.converged ? 0 : 1;
  }
  std::cout << "scalar calibration of " << o.file << " (modulus " << (modulus == Modulus::norm ? "norm" : "projection")
            << ", |I| = " << (ao.magnitude_auto ? std::string("auto") : o.magnitude) << ")\n";
  if (in.log)
    std::cout << in.detection.intervals.size() << " static intervals in " << in.log->size() << " rows (window "
              << in.detection.window << " samples, threshold " << std::setprecision(4) << in.detection.threshold << ")\n";
  std::cout << r.positions << " positions, " << r.samples << " samples, " << r.iterations << " iterations"
            << (r.converged ? "" : " (not converged)") << (a.started ? ", from an ellipsoid start" : "") << "\n";
  std::cout << std::setprecision(6);
  const Vec3 b = a.correction.offset;
  for (int k = 0; k < 9; ++k) {
    const double v = k < 3 ? b(k) : k < 6 ? a.scale_deviation(k - 3) : a.correction.nonorthogonality(k - 6);
    const double s = k < 3 ? a.bias_std(k) : k < 6 ? a.scale_deviation_std(k - 3) : a.nonorthogonality_std(k - 6);
    std::cout << "  " << std::left << std::setw(11) << kParameterNames[k] << std::right << std::setw(14) << v;
    if (have_std) std::cout << "  +- " << s;
    std::cout << (k < 3 ? "  (file units)" : k < 6 ? "" : "  rad") << "\n";
  }
  if (a.started) {
    std::cout << "physical = matrix (raw - offset), nominal gain " << a.nominal_gain << " file units per unit:\n";
    for (int i = 0; i < 3; ++i)
      std::cout << "  " << std::setw(14) << a.correction.matrix(i, 0) << std::setw(14) << a.correction.matrix(i, 1)
                << std::setw(14) << a.correction.matrix(i, 2) << "\n";
  }
  std::cout << "residual rms " << r.residual_rms << ", noise " << (have_std ? std::to_string(r.noise) : "n/a") << " ("
            << (r.noise_source == NoiseSource::scatter     ? "scatter of samples within positions"
                : r.noise_source == NoiseSource::residuals ? "residuals, N - 9 degrees of freedom"
                                                           : "not estimable")
            << ")\n";
  std::cout << "program measured: N = " << ev.positions << ", D " << ev.D << ", A " << ev.A << ", E " << ev.E << ", S "
            << ev.S << ", thetas " << ev.theta_bias << " " << ev.theta_scale << " " << ev.theta_nonorth
            << ", condition " << ev.condition << "; efficiency on " << region.text() << ":";
  for (auto c : kCriteria) std::cout << " " << criterion_name(c) << " " << advice.efficiency[static_cast<std::size_t>(c.index())];
  std::cout << "\n";
  const auto now = rms_errors(ev);
  std::cout << "RMS errors per unit noise (bias, scale, nonorth): " << now[0] << " " << now[1] << " " << now[2] << "\n";
  for (const auto& s : advice.suggested)
    std::cout << "  add " << std::setprecision(4) << s.position(0) << ", " << s.position(1) << ", " << s.position(2)
              << ": " << criterion_name(criterion) << " " << std::setprecision(6) << s.value << ", RMS errors "
              << s.errors[0] << " " << s.errors[1] << " " << s.errors[2] << "\n";
  return r.converged ? 0 : 1;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_text(app, "--measurements", o->file, "FILE",
           {"bench data: CSV with ix,iy,iz [,position] [,x,y,z], or a raw log: CSV with t,ix,iy,iz or text t ix iy iz",
            "file path", kRequired});
  add_checked_text(app, "--magnitude", o->magnitude, "M|auto",
                   {"modulus |I| of the measured vector, or auto for a field of unknown strength", "physical units",
                    kRequired},
                   [](const std::string& s) -> std::string {
                     if (s == "auto") return "";
                     try {
                       std::size_t used = 0;
                       const double v = std::stod(s, &used);
                       if (used == s.size() && std::isfinite(v) && v > 0) return "";
                     } catch (...) {
                     }
                     return "must be a positive number or auto, got '" + s + "'";
                   });
  add_choice(app, "--modulus", o->modulus, {"norm", "projection"},
             {"the modulus: norm (m_I, |measured|) or projection (m_II, onto the nominal direction)"});
  add_choice(app, "--format", o->format, {"auto", "csv", "text"},
             {"the file: auto (text when the first line starts with a number), csv, or text (t ix iy iz, no header)"});
  add_number(app, "--still", o->intervals.still_seconds, positive_number(),
             {"a raw log's initial still period, whose noise sets the static threshold", "seconds"});
  add_number(app, "--window", o->intervals.window_seconds, positive_number(),
             {"the moving variance's window in a raw log", "seconds"});
  add_number(app, "--threshold-factor", o->intervals.threshold_factor, positive_number(),
             {"static where the window's variance norm stays below this times the still period's", "none"});
  add_number(app, "--min-interval", o->intervals.min_seconds, positive_number(),
             {"the shortest static interval that counts as a position", "seconds"});
  add_choice(app, "--weights", o->weights, {"auto", "samples", "positions"},
             {"each position's weight: its number of samples, or 1; auto: positions for a raw log, samples otherwise"});
  add_switch(app, "--keep-outliers", o->keep_outliers,
             "keep samples more than 10 robust scales from their position's median (excluded by default)");
  add_integer(app, "--suggest", o->suggest, 0, 100, {"how many positions to suggest adding", "positions"});
  add_criterion(app, o->criterion, "D");
  add_region_option(app, o->regions);
  add_model(app, o->model);
  add_text(app, "--out", o->out, "FILE", {"also write the JSON object to FILE (for `scalcal correct`)", "file path"});
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"calibrate", kUsage,
                        "scalar calibration (eqs. 3-6) in any units, from grouped samples or a raw log: bias, scale "
                        "factors, non-orthogonality with standard errors, the full correction, the program's quality "
                        "and what to add",
                        40, setup});

}  // namespace
}  // namespace scalcal::cli
