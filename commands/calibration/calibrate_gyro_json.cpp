// The JSON form of a gyro's calibration (calibrate_gyro.hpp): the accelerometer's file header and
// correction keys, so export and correct read it alike, then what the method measured.
#include <cmath>

#include "commands/calibration/calibrate_gyro.hpp"
#include "commands/calibration/calibrate_json.hpp"
#include "commands/calibration/calibration_file.hpp"
#include "commands/core/tool_info.hpp"
#include "numeric/calibration/units.hpp"
#include "numeric/criteria/registry.hpp"

namespace scalcal::commands {
namespace {

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(); }
Json triple(const Vec3& v) { return Json{number_or_null(v(0)), number_or_null(v(1)), number_or_null(v(2))}; }
Json rows_of(const Mat3& m) { return Json{triple(m.row(0)), triple(m.row(1)), triple(m.row(2))}; }

// Rate table and turns: the model's parameters by the model's names, as calibrate writes them and
// the calibration-file reader checks them: bias in raw units, scale deviation against the nominal
// gain (1 when the raw units are the physical ones within 10 %, else the gains' geometric mean),
// non-orthogonality in rad; the gains themselves (raw units per physical unit) beside them.
void add_scalar(const GyroCalibrateResult& r, Json& j) {
  const gyro::KnownModulusCalibration& c = *r.scalar;
  const Vec3 k = c.parameters.segment<3>(3);
  const double geometric = std::cbrt(k(0) * k(1) * k(2));
  const double nominal = std::abs(geometric - 1) < 0.1 ? 1.0 : geometric;
  Json p = Json::object(), se = Json::object(), pred = Json::object(), gain = Json::array(), gain_se = Json::array();
  const auto names = visit_model(c.model, [](auto m) {
    std::vector<std::string> n;
    for (const auto& x : decltype(m)::parameter_names) n.emplace_back(x);
    return n;
  });
  for (std::size_t q = 0; q < names.size(); ++q) {
    const std::string name(names[q]);
    // bias_* are entries 0-2, scale_* 3-5 (as gains), nonorth_* 6-8 of the estimator's nine.
    const int at = name.rfind("bias", 0) == 0    ? name.back() - 'x'
                   : name.rfind("scale", 0) == 0 ? 3 + (name.back() - 'x')
                                                 : 6 + static_cast<int>(q % 3);
    const bool scale = at >= 3 && at < 6;
    p[name] = number_or_null(scale ? c.parameters(at) / nominal - 1 : c.parameters(at));
    se[name] = number_or_null(scale ? c.standard_error(at) / nominal : c.standard_error(at));
    pred[name] = number_or_null(scale ? c.predicted_std(at) / nominal : c.predicted_std(at));
  }
  for (int a = 0; a < 3; ++a)
    gain.push_back(number_or_null(k(a))), gain_se.push_back(number_or_null(c.standard_error(3 + a)));
  j["parameters"] = p;
  j["standard_error"] = se;
  j["predicted_std"] = pred;
  j["nominal_gain"] = nominal;
  j["gain"] = gain;
  j["gain_std"] = gain_se;
  j["model"] = std::string(model_name(c.model));
  j["model_reason"] = r.model_reason;
  j["scale_deviation"] = triple(c.meter.scale_deviation);
  j["nonorthogonality"] = triple(c.correction.nonorthogonality);
  j["item_variance_scale"] = c.item_scale;
  j["rest_variance_scale"] = r.rests.empty() ? Json() : Json(c.rest_scale);
  j["dof"] = c.item_dof + (r.rests.empty() ? 0.0 : c.rest_dof);
  j["condition"] = number_or_null(c.condition);
  j["converged"] = c.summary.converged();
  j["message"] = c.summary.message;
  j["iterations"] = c.summary.iterations;
  Json items = Json::array();
  for (std::size_t i = 0; i < r.items.size(); ++i) {
    const auto& it = r.items[i];
    items.push_back(Json{{"line", it.line},
                         {"start", it.start},
                         {"end", it.stop},
                         {"mean", triple(it.mean)},
                         {"modulus", it.modulus},
                         {"direction", triple(c.directions[i])},
                         {"residual", c.residuals[i]}});
  }
  j[r.method == GyroMethod::rate_table ? "segments" : "turns"] = items;
  if (r.program) {
    Json program{{"positions", r.program->positions},
                 {"rank", r.program->rank},
                 {"condition", number_or_null(r.program->condition)}};
    Json eff = Json::object();
    std::size_t k = 0;
    for (CriterionKind cr : kCriteria) {
      program[std::string(criterion_name(cr))] = number_or_null(r.program->value(cr));
      eff[std::string(criterion_name(cr))] = number_or_null(k < r.efficiency.size() ? r.efficiency[k] : NAN);
      ++k;
    }
    program["efficiency"] = eff;
    j["program"] = program;
    Json suggested = Json::array();
    // As calibrate's suggestions are written: one object per position (a gyro's has no criterion value).
    for (const Vec3& x : r.suggested) suggested.push_back(Json{{"position", triple(x)}});
    j["suggested"] = suggested;
  }
  if (r.method == GyroMethod::known_turns) j["motions_skipped"] = r.motions_skipped;
}

void add_hand(const GyroCalibrateResult& r, Json& j) {
  const gyro::HandRotationCalibration& h = *r.hand;
  const double k = r.matrix(0, 0) / h.matrix(0, 0);  // the physical unit per rad/s
  Mat3 se;
  for (int a = 0; a < 9; ++a) se(a / 3, a % 3) = k * h.standard_error(a);
  j["matrix_std"] = rows_of(se);
  j["offset_std"] = triple(h.standard_error.tail<3>());
  Mat3 pred;
  for (int a = 0; a < 9; ++a) pred(a / 3, a % 3) = k * h.predicted_std(a);
  j["matrix_predicted_std"] = rows_of(pred);
  j["offset_predicted_std"] = triple(h.predicted_std.tail<3>());
  j["rotation_to_accelerometer"] = triple(r.rotation);
  if (r.paper_form) {
    j["scale"] = triple(r.paper_form->scale);
    j["nonorthogonality"] = triple(r.paper_form->nonorthogonality);
  }
  j["converged"] = h.summary.converged();
  j["message"] = h.summary.message;
  j["iterations"] = h.summary.iterations;
  j["misfit_rms_rad"] = h.misfit.angle_rms;
  j["misfit_chord_rms"] = h.misfit.chord_rms;
  j["rotation_variance_scale"] = h.rotation_scale;
  j["rest_variance_scale"] = h.rest_scale;
  Json pairs = Json::array();
  for (const auto& p : h.misfit.pairs) {
    const auto& a = r.poses[static_cast<std::size_t>(p.from)];
    pairs.push_back(Json{{"from_sample", a.end}, {"seconds", p.seconds}, {"misfit_rad", p.angle}});
  }
  j["pairs"] = pairs;
  Json poses = Json::array();
  for (const auto& p : r.poses)
    poses.push_back(Json{{"begin", p.begin}, {"end", p.end}, {"gravity", triple(p.gravity)}});
  j["poses"] = poses;
  j["accelerometer"] = calibration_file_json(*r.accelerometer);
}

}  // namespace

Json gyro_calibration_file_json(const GyroCalibrateResult& r) {
  const auto label = [](const std::string& s) { return s.empty() ? Json() : Json(s); };
  CalibrationUnits units;
  bool counts = false;
  if (!r.request.raw_units.empty()) {
    units.raw = parse_unit(r.request.raw_units);
    counts = !units.raw;
  }
  if (!r.request.physical_units.empty()) units.physical = parse_unit(r.request.physical_units);
  units.unit_modulus = r.request.magnitude && r.request.magnitude->automatic();
  Json j{{"format_version", kCalibrationFormatVersion},
         {"created", utc_now_iso8601()},
         {"tool", Json{{"name", "scalcal"}, {"version", tool_version()}, {"commit", tool_commit()}}},
         {"sensor", label(r.request.sensor)},
         {"units", units_json(units, counts)},
         {"instrument", "gyro"},
         {"method", gyro_method_name(r.method)},
         {"offset", triple(r.offset)},
         {"matrix", rows_of(r.matrix)},
         {"linear", true},
         {"rows", r.rows},
         {"window", r.detection.window},
         {"noise_floor", number_or_null(r.detection.still_variance)},
         {"sample_rate", r.detection.sample_period > 0 ? Json(1 / r.detection.sample_period) : Json()},
         {"noise", number_or_null(r.noise)}};
  if (r.scalar && r.request.magnitude && r.request.magnitude->column.empty())
    j["magnitude"] = r.request.magnitude->rate ? Json(*r.request.magnitude->rate) : Json("auto");
  if (r.paper_form) j["bias"] = triple(r.paper_form->offset);
  Json rests = Json::array();
  for (const auto& x : r.rests)
    rests.push_back(Json{{"line", x.line}, {"start", x.span.start}, {"end", x.span.stop}, {"mean", triple(x.mean)}});
  j["rests"] = rests;
  if (r.scalar) add_scalar(r, j);
  if (r.hand) add_hand(r, j);
  Json warnings = Json::array();
  for (const auto& w : r.warnings) warnings.push_back(w.subject.empty() ? w.message : w.subject + ": " + w.message);
  j["warnings"] = warnings;
  return j;
}

}  // namespace scalcal::commands
