#include "experiments/cli/calibrate_model.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"
#include "numeric/calibration/full_correction.hpp"
#include "numeric/calibration/model_calibration.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/region/region_limit.hpp"

namespace scalcal::cli {

// A meter more than this far from unit gain (mean modulus / |I|) is outside what the linearised
// estimator starts from; the paper9 path fits an ellipsoid first, the other models do not.
constexpr double kGainTolerance = 0.2;

// " D 1.7e+07, A 78, E 18, S 18": every registered criterion, in the registry's order.
std::string criteria_text(const ModelEvaluation& ev) {
  std::ostringstream t;
  for (auto c : kCriteria) t << (c.index() ? ", " : " ") << criterion_name(c) << " " << ev.value(c);
  return t.str();
}

std::string not_identifiable_text(ModelKind model) {
  const std::string rotation =
      "the rotation part of the misalignment (three angles) leaves every modulus unchanged and is not estimated";
  const std::string_view name = model_name(model);
  if (name == "bias3")
    return rotation +
           "; scale factors are taken as exactly 1 and the axes as orthogonal: their errors go into the "
           "residual";
  if (name == "axis6") return rotation + "; the axes are taken as orthogonal: non-orthogonality goes into the residual";
  if (name == "cubic12")
    return rotation +
           "; at one magnitude the cubic term is identified as c_i |I| only (it cannot be told from a "
           "scale factor that depends on the magnitude), and never from positions along the axes alone, "
           "where x^3 = x makes it the bias";
  return rotation;
}

Report model_calibration_report(const ModelCalibrationRequest& q, const std::vector<PositionSamples>& data) {
  const std::string name(model_name(q.model));
  const int P = model_parameters(q.model);
  try {
    meter_indices(q.model);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("calibrate: ") + e.what());
  }
  if (static_cast<int>(data.size()) < P)
    throw InputError(q.file, 0,
                     std::to_string(data.size()) + " positions cannot identify the " + std::to_string(P) +
                         " parameters of --model " + name);
  const Program directions{position_directions(data, q.modulus)};
  const ModelEvaluation ev = evaluate(q.model, directions);
  if (!ev.full_rank()) throw InputError(q.file, 0, "--model " + name + ": " + rank_deficiency(ev));
  double gain = 0;
  for (const auto& p : data) gain += p.mean().norm() / q.magnitude;
  gain /= static_cast<double>(data.size());
  if (std::abs(gain - 1) > kGainTolerance) {
    std::ostringstream s;
    s << std::setprecision(4) << "the measurements' mean modulus is " << gain << " times --magnitude " << q.magnitude
      << ": --model " << name << " calibrates a meter near unit gain in the units of --magnitude (the paper9 model "
      << "starts from an ellipsoid fit and takes any units)";
    throw InputError(q.file, 0, s.str());
  }
  CalibrationOptions co;
  co.modulus = q.modulus;
  co.magnitude = q.magnitude;
  co.weight_by_samples = q.weight_by_samples;
  const ModelCalibration r = calibrate_model(q.model, data, co);
  const bool have_std = r.noise_source != NoiseSource::none;
  if (!have_std)
    std::cerr << "scalcal calibrate: " << q.file << ": warning: " << P << " positions with one sample each fit "
              << "exactly; the noise and the standard errors cannot be estimated\n";
  if (!r.converged)
    std::cerr << "scalcal calibrate: " << q.file << ": warning: the iteration did not converge after " << r.iterations
              << " iterations (errors too large for the linearised model?)\n";

  Json params = Json::array();
  for (int k = 0; k < P; ++k)
    params.push_back(Json{{"name", std::string(ev.parameter_names[static_cast<std::size_t>(k)])},
                          {"value", r.X(k)},
                          {"std", have_std ? Json(r.X_std(k)) : Json()}});
  Json eff = Json::object();
  std::string eff_text;
  for (CriterionKind c : kCriteria) {
    const auto limit = stated_limit(q.model, criterion_name(c));
    const double e = limit ? efficiency(c, limit->value, ev.value(c), P) : std::nan("");
    eff[std::string(criterion_name(c))] = limit ? Json(e) : Json();
    std::ostringstream t;
    t << " " << criterion_name(c) << " " << std::setprecision(4) << e;
    eff_text += t.str();
  }
  Json program{{"positions", ev.positions}, {"rank", ev.rank}, {"condition", ev.condition}};
  for (auto c : kCriteria) program[std::string(criterion_name(c))] = ev.value(c);
  program["efficiency"] = eff;
  for (int g = 0; g < 4; ++g)
    if (ev.has_group(static_cast<ParameterGroup>(g)))
      program["theta_" + std::string(kGroupNames[static_cast<std::size_t>(g)])] = ev.theta[static_cast<std::size_t>(g)];
  const Vec3 offset = r.meter.linear.bias;
  Json j{{"model", name},
         {"parameters", params},
         {"offset", Json{offset(0), offset(1), offset(2)}},
         {"iterations", r.iterations},
         {"converged", r.converged},
         {"residual_rms", r.residual_rms},
         {"noise", have_std ? Json(r.noise) : Json()},
         {"noise_source", r.noise_source == NoiseSource::scatter     ? "scatter"
                          : r.noise_source == NoiseSource::residuals ? "residuals"
                                                                     : "none"},
         {"positions", r.positions},
         {"samples", r.samples},
         {"modulus", q.modulus == Modulus::norm ? "norm" : "projection"},
         {"magnitude", q.magnitude},
         {"weights", q.weight_by_samples ? "samples" : "positions"},
         {"not_identifiable", not_identifiable_text(q.model)},
         {"program", program}};
  // A linear meter's correction for `scalcal correct` (physical = matrix (raw - offset)); cubic12's
  // correction is not linear, so it has none and `correct` says so.
  if (r.meter.cubic.isZero()) {
    const FullCorrection c = correction_of(r.meter.linear);
    Json rows = Json::array();
    for (int i = 0; i < 3; ++i) rows.push_back(Json{c.matrix(i, 0), c.matrix(i, 1), c.matrix(i, 2)});
    j["matrix"] = rows;
  }
  if (!q.out.empty()) write_output_file(q.out, [&](std::ostream& f) { write_json(f, j); });
  std::ostringstream text;
  text << "scalar calibration of " << q.file << ", model " << name << " (" << P << " parameters, modulus "
       << (q.modulus == Modulus::norm ? "norm" : "projection") << ", |I| = " << q.magnitude << ")\n"
       << r.positions << " positions, " << r.samples << " samples, " << r.iterations << " iterations"
       << (r.converged ? "" : " (not converged)") << "\n"
       << std::setprecision(6);
  for (int k = 0; k < P; ++k) {
    text << "  " << std::left << std::setw(11) << ev.parameter_names[static_cast<std::size_t>(k)] << std::right
         << std::setw(14) << r.X(k);
    if (have_std) text << "  +- " << r.X_std(k);
    text << "\n";
  }
  text << "(bias over |I|, scale deviation, gamma in rad, c |I|; offset in file units " << offset(0) << " " << offset(1)
       << " " << offset(2) << ")\n"
       << "not identified: " << not_identifiable_text(q.model) << "\n"
       << "residual rms " << r.residual_rms << ", noise " << (have_std ? std::to_string(r.noise) : "n/a") << "\n"
       << "program measured under " << name << ":" << criteria_text(ev) << ", condition " << ev.condition << "; efficiency (limit / value, D as its " << P << "th root):" << eff_text
       << "\n";
  return Report{j, text.str(), r.converged ? 0 : 1};
}

}  // namespace scalcal::cli
