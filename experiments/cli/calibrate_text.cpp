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
    << (r.request.modulus == Modulus::norm ? "norm" : "projection") << ", |I| = " << r.request.magnitude << ")\n";
  if (r.detection) {
    const auto& d = *r.detection;
    t << std::setprecision(4) << d.intervals.size() << " static intervals in " << r.rows << " rows (window " << d.window
      << " samples, noise floor " << d.still_variance << " from "
      << (d.floor_from_still ? "the first --still seconds" : "the log's quiet windows") << ", threshold " << d.threshold
      << ")\n";
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
  const std::vector<int> index = meter_indices(r.model);
  const bool small_dof = a.dof > 0 && a.dof < 5;
  t << std::setprecision(6);
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    const int m = index[k];
    const double v = m < 3   ? a.correction.offset(m)
                     : m < 6 ? a.scale_deviation(m - 3)
                     : m < 9 ? a.correction.nonorthogonality(m - 6)
                             : a.estimate.X(i);
    const double p = a.predicted_std(i), q = a.achieved_std(i), s = a.standard_error(i);
    t << "  " << std::left << std::setw(11) << names[k] << std::right << std::setw(14) << v;
    if (std::isfinite(s)) {
      t << "  +- " << std::setw(11) << std::left << or_na(s, 3) << std::right << " ("
        << (std::isnan(q) || (!std::isnan(p) && p >= q) ? "noise" : "residuals") << ")";
      if (small_dof) t << "  95 %: +- " << or_na(r.t95 * s, 3);
    }
    t << (m < 3 ? "  file units" : m < 6 ? "  of the nominal gain" : m < 9 ? "  rad" : "  c |I|") << "\n";
  }
  t << "gain (file units per " << (r.request.magnitude == "auto" ? "field strength" : "physical unit") << "):";
  for (int i = 0; i < 3; ++i) t << " " << or_na(a.gain(i)) << " +- " << or_na(a.gain_std(i), 3);
  t << "\n";
  if (std::isfinite(r.field_strength))
    t << "field strength (--magnitude auto): " << or_na(r.field_strength) << " +- " << or_na(r.field_strength_std, 3)
      << " file units (with the scale factors' geometric mean as 1)\n";
  t << "standard errors: the larger of the noise-based and the residual-based";
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
    << (e.noise_source != NoiseSource::none ? or_na(e.noise) : std::string("n/a")) << "\n";
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
