// The text of `calibrate` (calibrate_text.hpp).
#include "experiments/cli/calibrate_text.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace scalcal::cli {
namespace {

using commands::CalibrateResult;

std::string or_na(double v, int digits = 6) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s << std::setprecision(digits) << v;
  return s.str();
}

void header(const CalibrateResult& r, std::ostream& t) {
  const auto& a = r.fit;
  t << "scalar calibration of " << r.file << " (modulus "
    << (r.request.modulus == Modulus::norm ? "norm" : "projection")
    << ", |I| = " << commands::magnitude_text(r.request.magnitude) << ")\n";
  if (r.instrument) t << "instrument " << instrument_name(*r.instrument) << ": " << r.instrument_reason << "\n";
  if (r.tumbling) {
    const auto& u = *r.tumbling;
    t << std::setprecision(4) << "every sample a position: " << u.samples_used << " of " << r.rows << " rows";
    if (!u.disturbed.empty()) {
      t << "; " << u.disturbed.size() << " disturbed stretch" << (u.disturbed.size() > 1 ? "es" : "")
        << " left out (seconds:";
      for (std::size_t k = 0; k < u.disturbed.size() && k < 5; ++k)
        t << " " << u.disturbed[k].start << "-" << u.disturbed[k].stop;
      t << (u.disturbed.size() > 5 ? " ...)" : ")");
    }
    t << "\ncovered: " << std::setprecision(3) << 100 * u.coverage.covered_share
      << " % of the sphere's 100 cells; largest uncovered cap " << std::setprecision(3) << u.coverage.largest_gap_deg
      << " degrees around " << std::setprecision(3) << u.coverage.gap_centre(0) << ", " << u.coverage.gap_centre(1)
      << ", " << u.coverage.gap_centre(2) << "\n";
  } else if (r.detection) {
    const auto& d = *r.detection;
    t << std::setprecision(4) << d.intervals.size() << " static intervals in " << r.rows << " rows (window " << d.window
      << " samples, noise floor " << d.still_variance << " from "
      << (d.floor_from_still ? "the first --still seconds" : "the log's quiet windows") << ", threshold " << d.threshold
      << ")\n";
    if (r.chunk_rows > 0)
      t << "taken as a stream: " << r.chunks << " chunks of " << r.chunk_rows
        << " rows, each sample judged once from the rows up to half a window after it\n";
    if (r.chosen) {
      const auto& c = *r.chosen;
      t << "detection chosen of " << c.scored << " candidates: window " << c.options.window_seconds
        << " s, threshold factor " << c.options.threshold_factor << ", poses of " << c.options.min_seconds
        << " s or more; predicted errors " << std::setprecision(3) << std::sqrt(c.score / c.default_score)
        << " of the default detection's (" << c.default_positions << " poses)\n";
    }
  }
  t << "model " << model_name(r.model) << ": " << r.model_reason << "\n";
  t << a.estimate.positions << " positions, " << a.estimate.samples << " samples, " << a.dof << " degrees of freedom, "
    << a.estimate.summary.iterations << " iterations"
    << (r.converged() ? "" : " (NOT converged: " + a.estimate.summary.message + ")")
    << (a.started ? ", from an ellipsoid start" : "") << "\n";
}

// Each parameter: value, the standard error to use and which one it is.
void parameters(const CalibrateResult& r, std::ostream& t) {
  const auto& a = r.fit;
  const auto& names = r.program.evaluation.parameter_names;
  const MeterSlots slots = meter_slots(r.model);
  const Eigen::VectorXd values = reported_values(a);
  const bool small_dof = a.dof > 0 && a.dof < 5;
  t << std::setprecision(6);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    const ParameterGroup group = slots[k].parameter.group;
    const double v = values(i);
    const double p = a.predicted_std(i), q = a.achieved_std(i), s = a.standard_error(i);
    t << "  " << std::left << std::setw(11) << names[k] << std::right << std::setw(14) << v;
    if (std::isfinite(s)) {
      // The noise-based error is from the scatter within positions or a log's second differences; a
      // "predicted" one computed from the residuals (one sample per position) is labelled so.
      const bool noise_based =
          a.estimate.noise_source == NoiseSource::scatter || a.estimate.noise_source == NoiseSource::differences;
      t << "  +- " << std::setw(11) << std::left << or_na(s, 3) << std::right << " ("
        << (a.model_std.size()                                             ? "model"
            : (std::isnan(q) || (!std::isnan(p) && p >= q)) && noise_based ? "noise"
                                                                           : "residuals")
        << ")";
      if (small_dof) t << "  95 %: +- " << or_na(r.t95 * s, 3);
    }
    t << (group == ParameterGroup::bias      ? "  file units"
          : group == ParameterGroup::scale   ? "  of the nominal gain"
          : group == ParameterGroup::nonorth ? "  rad"
                                             : "  c |I|")
      << "\n";
  }
  t << "gain (file units per "
    << (!r.request.magnitude ? "unit field: the field as each axis sees it" : "physical unit") << "):";
  for (int i = 0; i < 3; ++i) t << " " << or_na(a.gain(i)) << " +- " << or_na(a.gain_std(i), 3);
  t << "\n";
  if (std::isfinite(r.field_strength))
    t << "field strength (--magnitude auto): " << or_na(r.field_strength) << " +- " << or_na(r.field_strength_std, 3)
      << " file units (the gains' geometric mean)\n";
  if (a.model_std.size())
    t << "standard errors: the error model's: noise within poses " << or_na(a.within_std, 3)
      << " per sample and scatter between poses " << or_na(a.between_std, 3) << " (REML)";
  else
    t << "standard errors: the larger of the noise-based and the residual-based";
  if (r.tumbling)
    t << " (the residuals' widened " << or_na(r.tumbling->correlation_factor, 3)
      << " times for their correlation in time: Newey-West over " << r.tumbling->lag << " samples)";
  if (a.noise_bias_replicates > 0)
    t << "\nnoise bias taken off (single samples' noise biases the fit by its square; estimated from "
      << a.noise_bias_replicates << " simulated copies with the log's noise): offsets (file units) "
      << or_na(a.offset_noise_bias(0), 3) << " " << or_na(a.offset_noise_bias(1), 3) << " "
      << or_na(a.offset_noise_bias(2), 3) << ", gains " << or_na(a.gain_noise_bias(0), 3) << " "
      << or_na(a.gain_noise_bias(1), 3) << " " << or_na(a.gain_noise_bias(2), 3) << " (in the gains' units)";
  if (a.chi_square)
    t << "; chi-square " << or_na(*a.chi_square, 4) << " for " << a.dof << " degrees of freedom (residuals "
      << or_na(std::sqrt(*a.chi_square / a.dof), 3) << " x the noise)";
  t << "\n";
}

void quality(const CalibrateResult& r, std::ostream& t) {
  const auto& a = r.fit;
  const auto& e = a.estimate;
  if (a.linear) {
    t << "physical = matrix (raw - offset), nominal gain " << or_na(a.nominal_gain) << ":\n";
    for (int i = 0; i < 3; ++i)
      t << "  " << std::setw(14) << a.correction.matrix(i, 0) << std::setw(14) << a.correction.matrix(i, 1)
        << std::setw(14) << a.correction.matrix(i, 2) << "\n";
  }
  t << "residual rms " << e.residual_rms << ", noise "
    << (e.noise_source != NoiseSource::none ? or_na(e.noise) : std::string("n/a"))
    << (e.noise_source == NoiseSource::differences ? " (one sample's, from second differences)" : "") << "\n";
  if (r.units.physical || r.units.unit_modulus || r.units.raw || r.raw_counts)
    t << "units: raw "
      << (r.units.raw    ? std::string(r.units.raw->name)
          : r.raw_counts ? "counts"
                         : "not given")
      << ", physical "
      << (r.units.unit_modulus ? std::string("unit modulus")
          : r.units.physical   ? std::string(r.units.physical->name)
                               : std::string("not given"))
      << " (" << r.units_reason << ")\n";
  if (!r.not_identifiable.empty()) {
    t << "not identifiable:";
    for (std::size_t k = 0; k < r.not_identifiable.size(); ++k) t << (k ? "; " : " ") << r.not_identifiable[k];
    t << "\n";
  }
  t << "not estimated: " << r.not_estimated << "\n";
  // The worst positions, so a bench engineer sees where the model and the data disagree.
  std::vector<std::size_t> order(r.positions.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](auto x, auto y) { return std::abs(r.positions[x].residual) > std::abs(r.positions[y].residual); });
  t << "worst positions (line, |corrected| - |I|, standardised):";
  for (std::size_t k = 0; k < order.size() && k < 3; ++k) {
    const auto& p = r.positions[order[k]];
    t << " line " << p.line << " " << or_na(p.residual, 3) << " " << or_na(p.standardised_residual, 3) << ";";
  }
  t << "\n";
  const ModelEvaluation& ev = r.program.evaluation;
  t << "program measured under " << model_name(r.model) << ": N = " << ev.positions;
  for (CriterionKind c : kCriteria) t << ", " << criterion_name(c) << " " << or_na(ev.value(c));
  t << ", condition " << or_na(ev.condition) << "; efficiency on " << r.program.region << ":";
  for (CriterionKind c : kCriteria)
    t << " " << criterion_name(c) << " " << or_na(r.program.efficiency[static_cast<std::size_t>(c.index())]);
  t << "\n";
  for (const auto& s : r.program.suggested) {
    t << "  add " << std::setprecision(4) << s.position(0) << ", " << s.position(1) << ", " << s.position(2) << ": "
      << criterion_name(r.request.criterion) << " " << std::setprecision(6) << s.value << ", RMS errors";
    for (double x : s.errors) t << " " << x;
    t << "\n";
  }
}

}  // namespace

std::string calibrate_text(const CalibrateResult& r) {
  std::ostringstream t;
  header(r, t);
  parameters(r, t);
  quality(r, t);
  return t.str();
}

}  // namespace scalcal::cli
