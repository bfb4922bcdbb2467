// The JSON form of a calibration: one schema for every model (calibrate_json.hpp).
#include "commands/calibration/calibrate_json.hpp"

#include "commands/core/tool_info.hpp"

#include <cmath>

namespace scalcal::commands {
namespace {

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(); }
Json triple(const Vec3& v) { return Json{number_or_null(v(0)), number_or_null(v(1)), number_or_null(v(2))}; }
Json rows_of(const Mat3& m) { return Json{triple(m.row(0)), triple(m.row(1)), triple(m.row(2))}; }

const char* noise_source_name(NoiseSource s) {
  return s == NoiseSource::scatter       ? "scatter"
         : s == NoiseSource::residuals   ? "residuals"
         : s == NoiseSource::differences ? "differences"
                                         : "none";
}

// The model's parameters in the reported units, as {name: value}.
Json parameters_json(const CalibrateResult& r, const Eigen::VectorXd& values) {
  const ModelEvaluation& ev = r.program.evaluation;
  Json j = Json::object();
  for (std::size_t k = 0; k < ev.parameter_names.size(); ++k)
    j[std::string(ev.parameter_names[k])] = number_or_null(values(static_cast<Eigen::Index>(k)));
  return j;
}

Json std_from(const CalibrateResult& r) {
  const AnyUnitsCalibration& a = r.fit;
  Json j = Json::object();
  const ModelEvaluation& ev = r.program.evaluation;
  for (std::size_t k = 0; k < ev.parameter_names.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    const double p = a.predicted_std(i), q = a.achieved_std(i);
    j[std::string(ev.parameter_names[k])] = a.model_std.size()                            ? Json("model")
                                            : std::isnan(p) && std::isnan(q)              ? Json()
                                            : std::isnan(q) || (!std::isnan(p) && p >= q) ? Json("predicted")
                                                                                          : Json("achieved");
  }
  return j;
}

// The samples inside interval k that are not its (a noisy window crossed the threshold): [first,
// last] sample indices of the log, from 0, inclusive.
Json breaks_of(const CalibrateResult& r, std::size_t k) {
  return r.detection && k < r.detection->intervals.size() ? Json(r.detection->intervals[k].breaks) : Json::array();
}

Json intervals_json(const CalibrateResult& r) {
  Json list = Json::array();
  if (r.tumbling) return list;  // every sample is a position: `tumbling` says what was used
  for (const auto& p : r.positions)
    list.push_back(Json{{"start", number_or_null(p.start)},
                        {"end", number_or_null(p.end)},
                        {"samples", p.samples},
                        {"mean", triple(p.mean)},
                        {"direction", triple(p.direction)},
                        {"residual", number_or_null(p.residual)},
                        {"standardised_residual", number_or_null(p.standardised_residual)},
                        {"breaks", breaks_of(r, static_cast<std::size_t>(&p - r.positions.data()))}});
  return list;
}

Json program_json(const CalibrateResult& r) {
  const ModelEvaluation& ev = r.program.evaluation;
  Json j{{"positions", ev.positions}, {"rank", ev.rank}, {"condition", number_or_null(ev.condition)}};
  for (CriterionKind c : kCriteria) j[std::string(criterion_name(c))] = number_or_null(ev.value(c));
  Json errors = Json::object();
  const double root = std::sqrt(static_cast<double>(ev.positions));
  for (int g = 0; g < 4; ++g)
    if (ev.has_group(static_cast<ParameterGroup>(g))) {
      const std::string name(kGroupNames[static_cast<std::size_t>(g)]);
      j["theta_" + name] = number_or_null(ev.theta[static_cast<std::size_t>(g)]);
      errors[name] = number_or_null(ev.theta[static_cast<std::size_t>(g)] / root);
    }
  j["errors"] = errors;
  j["region"] = r.program.region;
  Json eff = Json::object();
  for (CriterionKind c : kCriteria)
    eff[std::string(criterion_name(c))] = number_or_null(r.program.efficiency[static_cast<std::size_t>(c.index())]);
  j["efficiency"] = eff;
  return j;
}

Json suggested_json(const CalibrateResult& r) {
  const ModelEvaluation& ev = r.program.evaluation;
  std::vector<std::string> groups;
  for (int g = 0; g < 4; ++g)
    if (ev.has_group(static_cast<ParameterGroup>(g))) groups.emplace_back(kGroupNames[static_cast<std::size_t>(g)]);
  Json list = Json::array();
  for (const auto& s : r.program.suggested) {
    Json errors = Json::object();
    for (std::size_t g = 0; g < groups.size() && g < s.errors.size(); ++g)
      errors[groups[g]] = number_or_null(s.errors[g]);
    list.push_back(Json{{"position", triple(s.position)},
                        {std::string(criterion_name(r.request.criterion)), number_or_null(s.value)},
                        {"errors", errors}});
  }
  return list;
}

Json motion_json(const CalibrateResult& r) {
  if (!r.motion) return Json();
  const LogMotion& m = *r.motion;
  return Json{
      {"moving_share", number_or_null(m.moving_share)},       {"noise", triple(m.noise)},
      {"noise_relative", number_or_null(m.noise_relative)},   {"moving_deviation", number_or_null(m.moving_deviation)},
      {"still_deviation", number_or_null(m.still_deviation)}, {"field_survives", m.field_survives()}};
}

Json tumbling_json(const CalibrateResult& r) {
  if (!r.tumbling) return Json();
  const TumblingReport& t = *r.tumbling;
  Json disturbed = Json::array();
  for (const auto& d : t.disturbed)
    disturbed.push_back(Json{{"start", d.start},
                             {"end", d.stop},
                             {"first_line", d.first_line},
                             {"last_line", d.last_line},
                             {"samples", d.samples()},
                             {"worst", d.worst}});
  return Json{{"samples_used", t.samples_used},
              {"disturbed", disturbed},
              {"covered_share", t.coverage.covered_share},
              {"largest_gap_deg", t.coverage.largest_gap_deg},
              {"gap_centre", triple(t.coverage.gap_centre)},
              {"noise", number_or_null(t.noise)},
              {"correlation_factor", number_or_null(t.correlation_factor)},
              {"newey_west_lag", t.lag},
              {"noise_bias", Json{{"replicates", r.fit.noise_bias_replicates},
                                  {"offset", triple(r.fit.offset_noise_bias)},
                                  {"gain", triple(r.fit.gain_noise_bias)}}}};
}

void add_log(const CalibrateResult& r, Json& j) {
  const IntervalDetection* d = r.detection ? &*r.detection : nullptr;
  j["rows"] = d ? Json(r.rows) : Json();
  j["nonfinite_rows"] = d ? Json(d->nonfinite) : Json();
  j["saturated_samples"] = d ? Json(d->saturated) : Json();
  j["window"] = d ? Json(d->window) : Json();
  j["noise_floor"] = d ? number_or_null(d->still_variance) : Json();
  j["noise_floor_source"] = d ? Json(d->floor_from_still ? "still" : "quiet_windows") : Json();
  j["static_threshold"] = d ? number_or_null(d->threshold) : Json();
  j["sample_rate"] = number_or_null(r.sample_rate);
  if (r.chunk_rows > 0) j["stream"] = Json{{"chunk_rows", r.chunk_rows}, {"chunks", r.chunks}};
  if (r.chosen)
    j["detection_choice"] =
        Json{{"window_seconds", r.chosen->options.window_seconds},
             {"threshold_factor", r.chosen->options.threshold_factor},
             {"min_interval_seconds", r.chosen->options.min_seconds},
             {"candidates_scored", r.chosen->scored},
             {"predicted_error_ratio", number_or_null(std::sqrt(r.chosen->score / r.chosen->default_score))},
             {"default_positions", r.chosen->default_positions}};
  else
    j["detection_choice"] = Json();
  j["motion"] = motion_json(r);
  j["tumbling"] = tumbling_json(r);
}

}  // namespace

Json to_json(const CalibrateResult& r) {
  if (r.thermal) return to_json(*r.thermal);
  const AnyUnitsCalibration& a = r.fit;
  const auto& e = a.estimate;
  Json j{{"instrument", r.instrument ? Json(std::string(instrument_name(*r.instrument))) : Json()},
         {"instrument_reason", r.instrument_reason},
         {"positions_from", r.tumbling    ? "every sample"
                            : r.detection ? "still intervals"
                                          : "bench positions"},
         {"model", std::string(model_name(r.model))},
         {"model_reason", r.model_reason},
         {"not_identifiable", r.not_identifiable},
         {"not_estimated", r.not_estimated},
         {"converged", r.converged()},
         {"termination", termination_name(e.summary.termination)},
         {"message", e.summary.message},
         {"iterations", e.summary.iterations},
         {"bias", triple(a.correction.offset)},
         {"scale_deviation", triple(a.scale_deviation)},
         {"nonorthogonality", triple(a.correction.nonorthogonality)},
         {"bias_std", triple(a.bias_std)},
         {"scale_deviation_std", triple(a.scale_deviation_std)},
         {"nonorthogonality_std", triple(a.nonorthogonality_std)},
         {"parameters", parameters_json(r, reported_values(r.fit))},
         {"predicted_std", parameters_json(r, a.predicted_std)},
         {"achieved_std", parameters_json(r, a.achieved_std)},
         {"model_std", a.model_std.size() ? parameters_json(r, a.model_std) : Json()},
         {"between_pose_std", number_or_null(a.between_std)},
         {"within_pose_std", number_or_null(a.within_std)},
         {"std_from", std_from(r)},
         {"dof", a.dof},
         {"t95", number_or_null(r.t95)},
         {"gain", triple(a.gain)},
         {"gain_std", triple(a.gain_std)},
         {"nominal_gain", a.nominal_gain},
         {"field_strength", number_or_null(r.field_strength)},
         {"field_strength_std", number_or_null(r.field_strength_std)},
         {"offset", triple(a.correction.offset)},
         {"matrix", a.linear ? rows_of(a.correction.matrix) : Json()},
         {"scale", triple(a.correction.scale)},
         {"linear", a.linear},
         {"residual_rms", e.residual_rms},
         {"noise", e.noise_source != NoiseSource::none ? Json(e.noise) : Json()},
         {"noise_source", noise_source_name(e.noise_source)},
         {"chi_square", a.chi_square ? Json(*a.chi_square) : Json()},
         {"chi_square_dof", a.chi_square ? Json(a.dof) : Json()},
         {"chi_square_p", a.chi_square ? Json(a.chi_square_p) : Json()},
         {"positions", e.positions},
         {"samples", e.samples},
         {"modulus", r.request.modulus == Modulus::norm ? "norm" : "projection"},
         {"magnitude", r.request.magnitude ? Json(a.magnitude) : Json("auto")},
         {"start", a.started ? "ellipsoid" : "none"},
         {"weights", r.weight_by_samples ? "samples" : "positions"}};
  Json lines = Json::array();
  for (const auto& x : r.excluded) lines.push_back(x.line);
  j["excluded_samples"] = lines;
  Json outliers = Json::array();
  for (int k : r.outliers) {
    const auto& p = r.positions[static_cast<std::size_t>(k)];
    outliers.push_back(Json{{"line", p.line}, {"residual", p.residual}, {"standardised", p.standardised_residual}});
  }
  j["outliers"] = outliers;
  j["intervals"] = intervals_json(r);
  add_log(r, j);
  j["program"] = program_json(r);
  j["suggested"] = suggested_json(r);
  return j;
}

// The file's own header first (what it is, when and by what it was made, of which meter, in which
// units), then the whole result; `region` is the region the program was judged on.
Json calibration_file_json(const CalibrateResult& r) {
  const auto label = [](const std::string& s) { return s.empty() ? Json() : Json(s); };
  Json j{{"format_version", kCalibrationFormatVersion},
         {"created", utc_now_iso8601()},
         {"tool", Json{{"name", "scalcal"}, {"version", tool_version()}, {"commit", tool_commit()}}},
         {"sensor", label(r.request.sensor)},
         {"instrument", r.instrument ? Json(std::string(instrument_name(*r.instrument))) : Json()},
         {"units", units_json(r.units, r.raw_counts)},
         {"units_reason", r.units_reason},
         {"region", r.thermal ? Json() : Json(r.program.region)}};
  const Json result = to_json(r);
  for (const auto& [key, value] : result.items())
    if (!j.contains(key)) j[key] = value;
  return j;
}

}  // namespace scalcal::commands
