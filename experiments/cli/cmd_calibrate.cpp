// `scalcal calibrate --measurements FILE --magnitude M [--modulus norm|projection] [--json]`: the
// paper's iterative scalar calibration of one meter from bench data.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

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
#include "numeric/calibration/data_checks.hpp"
#include "numeric/calibration/goodness_of_fit.hpp"
#include "numeric/calibration/meter_model.hpp"
#include "numeric/calibration/outlier_samples.hpp"
#include "numeric/calibration/scalar_calibration.hpp"

namespace scalcal::cli {
namespace {

constexpr const char* kUsage = "calibrate --measurements FILE --magnitude M [--modulus norm|projection] [--keep-outliers] [--json]";

Json triple(const Vec3& v) { return Json{v(0), v(1), v(2)}; }
Json triple_or_null(const Vec3& v, bool ok) { return ok ? triple(v) : Json(); }
Json excluded_lines(const std::vector<ExcludedSample>& out) {
  Json lines = Json::array();
  for (const auto& e : out) lines.push_back(e.line);
  return lines;
}

struct Options {
  std::string file, modulus = "norm";
  double magnitude = 0;
  bool json = false, keep_outliers = false;
};

int run(const Options& o) {
  const bool json = o.json;
  const std::string* file = &o.file;
  const double M = o.magnitude;
  const Modulus modulus = o.modulus == "norm" ? Modulus::norm : Modulus::projection;

  auto data = read_measurements_csv(*file, modulus == Modulus::projection);
  std::vector<ExcludedSample> excluded;
  if (!o.keep_outliers) excluded = exclude_outlier_samples(data);
  if (!excluded.empty()) std::cerr << "scalcal calibrate: " << *file << ": warning: " << outlier_warning(excluded) << "\n";
  check_calibration_data(*file, data, modulus, M);
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
                                                                    : "none"},
        {"excluded_samples", excluded_lines(excluded)}});
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
           {"bench data: CSV with ix,iy,iz [,position] [,x,y,z]", "file path", kRequired});
  add_number(app, "--magnitude", o->magnitude, positive_number(),
             {"modulus |I| of the measured vector", "the file's units", kRequired});
  add_choice(app, "--modulus", o->modulus, {"norm", "projection"},
             {"the modulus: norm (m_I, |measured|) or projection (m_II, onto the nominal direction)"});
  add_switch(app, "--keep-outliers", o->keep_outliers,
             "keep samples more than 10 robust scales from their position's median (excluded by default)");
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"calibrate", kUsage,
                        "iterative scalar calibration (eqs. 3-6): bias, scale-factor deviations, non-orthogonality "
                        "and their standard errors from bench measurements",
                        40, setup});

}  // namespace
}  // namespace scalcal::cli
