// `scalcal calibrate --measurements FILE --magnitude M [--modulus norm|projection] [--json]`: the
// paper's iterative scalar calibration of one meter from bench data.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include <boost/math/distributions/chi_squared.hpp>
#include <memory>
#include <sstream>
#include <iomanip>
#include <iostream>

#include "experiments/cli/command.hpp"
#include "experiments/cli/evaluation_report.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/measurements_csv.hpp"
#include "numeric/calibration/meter_model.hpp"
#include "numeric/calibration/scalar_calibration.hpp"

namespace scalcal::cli {
namespace {

constexpr const char* kUsage = "calibrate --measurements FILE --magnitude M [--modulus norm|projection] [--json]";

// Everything that makes the data unusable is reported before the estimator runs.
void check_data(const std::string& file, const std::vector<PositionSamples>& data, Modulus modulus, double M) {
  const int P = static_cast<int>(data.size());
  if (P < kParameters)
    throw InputError(file, 0, std::to_string(P) + " distinct positions; scalar calibration estimates 9 parameters "
                                                  "and needs at least 9 positions");
  std::vector<double> ratio;
  for (const auto& p : data) ratio.push_back(p.mean().norm() / M);
  std::nth_element(ratio.begin(), ratio.begin() + P / 2, ratio.end());
  const double median = ratio[P / 2];
  if (median < 0.5 || median > 2.0) {
    std::ostringstream s;
    s << "the measured modulus is " << median << " times --magnitude " << M
      << "; the model needs it near 1 (wrong --magnitude or units?)";
    throw InputError(file, 0, s.str());
  }
  Program directions;
  directions.positions = position_directions(data, modulus);
  const Evaluation ev = evaluate(directions);
  if (!ev.full_rank())
    throw InputError(file, 0, "the measured positions form a " + rank_deficiency(ev));
  if (ev.condition > kIllConditioned) throw InputError(file, 0, "the measured positions form an " + ill_conditioning(ev));
}

// Goodness of fit: the residual J_i = m_i / |I| - 1 of each position's mean has the standard
// error (noise / |I|) / sqrt(n_i) by the fit's own noise estimate (the scatter within positions),
// so sum z_i^2 with z_i = J_i / that error is chi-square with P - 9 degrees of freedom. A p-value
// below 1e-3 means the fit contradicts its noise estimate: mislabelled positions (two directions
// under one id), outliers or a model that does not fit; the positions with |z| > 3 are named.
struct GoodnessOfFit {
  double chi_square = 0, p = 1;
  int dof = 0;
  std::vector<std::pair<double, int>> disagreeing;  // (|z|, line of the position's first sample), worst first
};
constexpr double kFitRejectP = 1e-3, kDisagreeZ = 3;

std::optional<GoodnessOfFit> goodness_of_fit(const std::vector<PositionSamples>& data, const CalibrationResult& r,
                                             Modulus modulus, double M) {
  if (r.noise_source != NoiseSource::scatter || !(r.noise > 0) || r.positions <= kParameters) return std::nullopt;
  const Meter meter = Meter::from_parameters(r.X, M);
  GoodnessOfFit g;
  g.dof = r.positions - kParameters;
  for (const auto& p : data) {
    const Vec3 c = meter.compensate(p.mean());
    const double m = modulus == Modulus::norm ? c.norm() : c.dot(p.nominal->normalized());
    const double z = (m - M) * std::sqrt(static_cast<double>(p.samples.size())) / r.noise;
    g.chi_square += z * z;
    if (std::abs(z) > kDisagreeZ) g.disagreeing.emplace_back(std::abs(z), p.line);
  }
  std::sort(g.disagreeing.rbegin(), g.disagreeing.rend());
  g.p = boost::math::cdf(boost::math::complement(boost::math::chi_squared(g.dof), g.chi_square));
  return g;
}

std::string fit_warning(const GoodnessOfFit& g) {
  std::ostringstream s;
  s << std::setprecision(4) << "the fit contradicts its own noise estimate: chi-square " << g.chi_square << " for "
    << g.dof << " degrees of freedom (p = " << std::setprecision(2) << g.p
    << ") of the position residuals against the scatter within positions; ";
  if (g.disagreeing.empty()) {
    s << "no single position stands out (model misfit?)";
  } else {
    s << "positions that disagree (first line, |residual| in standard errors):";
    for (std::size_t i = 0; i < std::min<std::size_t>(g.disagreeing.size(), 8); ++i)
      s << (i ? "," : "") << " line " << g.disagreeing[i].second << " (" << std::setprecision(3)
        << g.disagreeing[i].first << ")";
    if (g.disagreeing.size() > 8) s << " and " << g.disagreeing.size() - 8 << " more";
    s << " (mislabelled positions or outliers?)";
  }
  return s.str();
}

Json triple(const Vec3& v) { return Json{v(0), v(1), v(2)}; }
Json triple_or_null(const Vec3& v, bool ok) { return ok ? triple(v) : Json(); }

struct Options {
  std::string file, modulus = "norm";
  double magnitude = 0;
  bool json = false;
};

int run(const Options& o) {
  const bool json = o.json;
  const std::string* file = &o.file;
  const double M = o.magnitude;
  const Modulus modulus = o.modulus == "norm" ? Modulus::norm : Modulus::projection;

  const auto data = read_measurements_csv(*file, modulus == Modulus::projection);
  check_data(*file, data, modulus, M);
  CalibrationOptions options;
  options.modulus = modulus;
  options.magnitude = M;
  const CalibrationResult r = calibrate(data, options);
  const bool have_std = r.noise_source != NoiseSource::none;
  if (!have_std)
    std::cerr << "scalcal calibrate: " << *file << ": warning: 9 positions with one sample each fit exactly; "
              << "the noise and the standard errors cannot be estimated\n";
  if (!r.converged)
    std::cerr << "scalcal calibrate: " << *file << ": warning: the iteration did not converge after " << r.iterations
              << " iterations (errors too large for the linearised model?)\n";

  const auto fit = goodness_of_fit(data, r, modulus, M);
  if (fit && fit->p < kFitRejectP) std::cerr << "scalcal calibrate: " << *file << ": warning: " << fit_warning(*fit) << "\n";

  const Vec3 scale = r.X.segment<3>(3), gamma = r.X.segment<3>(6);
  const Vec3 scale_std = r.X_std.segment<3>(3), gamma_std = r.X_std.segment<3>(6);
  if (json) {
    print_json(Json{
        {"bias", triple(r.bias(M))},
        {"scale_deviation", triple(scale)},
        {"nonorthogonality", triple(gamma)},
        {"bias_std", triple_or_null(r.bias_std(M), have_std)},
        {"scale_deviation_std", triple_or_null(scale_std, have_std)},
        {"nonorthogonality_std", triple_or_null(gamma_std, have_std)},
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
                                                                    : "none"}});
  } else {
    std::cout << "scalar calibration of " << *file << " (modulus " << (modulus == Modulus::norm ? "norm" : "projection")
              << ", |I| = " << M << ")\n"
              << r.positions << " positions, " << r.samples << " samples, " << r.iterations << " iterations"
              << (r.converged ? "" : " (not converged)") << "\n";
    const char* names[9] = {"bias_x", "bias_y", "bias_z", "scale_x", "scale_y", "scale_z",
                            "nonorth_xy", "nonorth_yz", "nonorth_zx"};
    const Vec3 b = r.bias(M), bs = r.bias_std(M);
    std::cout << std::setprecision(6);
    for (int k = 0; k < 9; ++k) {
      const double v = k < 3 ? b(k) : r.X(k);
      const double s = k < 3 ? bs(k) : r.X_std(k);
      std::cout << "  " << std::left << std::setw(11) << names[k] << std::right << std::setw(14) << v;
      if (have_std) std::cout << "  +- " << s;
      std::cout << (k < 3 ? "  (file units)" : k < 6 ? "" : "  rad") << "\n";
    }
    std::cout << "residual rms " << r.residual_rms << ", noise " << (have_std ? std::to_string(r.noise) : "n/a")
              << " (" << (r.noise_source == NoiseSource::scatter ? "scatter of samples within positions"
                          : r.noise_source == NoiseSource::residuals ? "residuals, N - 9 degrees of freedom"
                                                                     : "not estimable")
              << ")\n";
  }
  return r.converged ? 0 : 1;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_text(app, "--measurements", o->file, "FILE",
           {"bench data: CSV with ix,iy,iz [,position] [,x,y,z]", "file path", kRequired})
      ->required();
  add_number(app, "--magnitude", o->magnitude, positive_number(),
             {"modulus |I| of the measured vector", "the file's units", kRequired})
      ->required();
  add_choice(app, "--modulus", o->modulus, {"norm", "projection"},
             {"the modulus: norm (m_I, |measured|) or projection (m_II, onto the nominal direction)"});
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"calibrate", kUsage,
                        "iterative scalar calibration (eqs. 3-6): bias, scale-factor deviations, non-orthogonality "
                        "and their standard errors from bench measurements",
                        40, setup});

}  // namespace
}  // namespace scalcal::cli
