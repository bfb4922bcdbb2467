// `scalcal simulate --program P --trials T --noise SIGMA [--bench-error DEG] [--modulus ...]
// [--model NAME] [--seed S] [--json]`: Monte-Carlo calibration of simulated meters, the empirical
// covariance of the estimates against sigma^2 K, the estimator's bias, and the effect of bench errors.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "experiments/cli/command.hpp"
#include "experiments/cli/evaluation_report.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/calibration/model_calibration.hpp"
#include "numeric/calibration/monte_carlo.hpp"
#include "numeric/model/paper9.hpp"

namespace scalcal::cli {
namespace {

constexpr const char* kUsage =
    "simulate --program P --trials T --noise SIGMA [--bench-error DEG] [--modulus norm|projection] [--model NAME] "
    "[--seed S] [--samples K] [--size A] [--json]";

const char* modulus_name(Modulus m) { return m == Modulus::norm ? "norm" : "projection"; }

Json result_json(const MonteCarloResult& r, Modulus m) {
  Json params = Json::array();
  for (int k = 0; k < static_cast<int>(r.truth.size()); ++k) {
    const double th = std::sqrt(r.theoretical_cov(k, k));
    const double se_mean = std::sqrt(r.empirical_cov(k, k) / std::max(1, r.converged));
    params.push_back(Json{{"name", std::string(r.names[static_cast<std::size_t>(k)])},
                          {"truth", r.truth(k)},
                          {"mean", r.mean(k)},
                          {"bias", r.mean(k) - r.truth(k)},
                          {"bias_in_std_errors", (r.mean(k) - r.truth(k)) / se_mean},
                          {"noise_free", r.noise_free(k)},
                          {"linearisation_error", r.noise_free(k) - r.truth(k)},
                          {"noise_bias_in_std_errors", (r.mean(k) - r.noise_free(k)) / se_mean},
                          {"empirical_std", std::sqrt(r.empirical_cov(k, k))},
                          {"theoretical_std", th},
                          {"std_ratio", std::sqrt(r.empirical_cov(k, k)) / th}});
  }
  Json te = Json::object(), tt = Json::object();
  for (int q = 0; q < 4; ++q) {
    if (std::isnan(r.theta_theoretical(q))) continue;  // a group the model lacks
    te[std::string(kGroupNames[q])] = r.theta_empirical(q);
    tt[std::string(kGroupNames[q])] = r.theta_theoretical(q);
  }
  return Json{{"modulus", modulus_name(m)},
              {"converged_trials", r.converged},
              {"mean_iterations", r.mean_iterations},
              {"parameters", params},
              {"theta_empirical", te},
              {"theta_theoretical", tt},
              {"std_sampling_error", r.std_sampling_error()},
              {"max_normalised_cov_difference", r.max_normalised_cov_difference()},
              {"mean_noise_ratio", r.mean_noise_ratio}};
}

void print_result(std::ostream& out, const MonteCarloResult& r, Modulus m) {
  out << "\nmodulus " << modulus_name(m) << ": " << r.converged << " converged trials, "
      << std::setprecision(3) << r.mean_iterations << " iterations on average\n";
  out << "  parameter        truth         bias   bias/se  lin. error   emp. std  theor. std   ratio\n";
  for (int k = 0; k < static_cast<int>(r.truth.size()); ++k) {
    const double th = std::sqrt(r.theoretical_cov(k, k));
    const double emp = std::sqrt(r.empirical_cov(k, k));
    const double se_mean = emp / std::sqrt(std::max(1, r.converged));
    out << "  " << std::left << std::setw(11) << r.names[static_cast<std::size_t>(k)] << std::right << std::setprecision(4)
        << std::setw(12) << r.truth(k) << std::setw(13) << r.mean(k) - r.truth(k) << std::setw(10)
        << std::setprecision(2) << (r.mean(k) - r.truth(k)) / se_mean << std::setprecision(4) << std::setw(12)
        << r.noise_free(k) - r.truth(k) << std::setw(11) << emp
        << std::setw(12) << th << std::setw(8) << std::setprecision(3) << emp / th << "\n";
  }
  out << "  theta (sqrt(N max var)/sigma)  empirical / theoretical:";
  for (int q = 0; q < 4; ++q)
    if (!std::isnan(r.theta_theoretical(q)))
      out << "  " << kGroupNames[q] << " " << std::setprecision(4) << r.theta_empirical(q) << " / "
        << r.theta_theoretical(q);
  out << "\n  sampling error of an empirical std: " << std::setprecision(2) << 100 * r.std_sampling_error()
      << "% (1 sigma); max normalised covariance difference " << std::setprecision(3)
      << r.max_normalised_cov_difference() << "; estimated noise / sigma " << std::setprecision(4)
      << r.mean_noise_ratio << "\n";
}

// The range of --noise sigma (relative to |I|) where the Monte-Carlo answers the question it is
// asked (README, `simulate`):
// - sigma >= 1 is refused: noise as large as the measured vector leaves no modulus to fit.
// - sigma < 1e-15 is refused: below the resolution of a double near |I| (2.2e-16), the simulated
//   noise is rounding; sigma^2 K underflows to 0 for sigma < 1e-154.
// - sigma > 0.01 warns: the modulus' second-order terms (~sigma^2) exceed 1 % of the noise, so
//   the empirical covariance departs from the linearised sigma^2 K.
// - sigma < 1e-9 warns: the estimator stops at |dX| < 1e4 eps = 2.2e-12, more than 0.2 % of the
//   spread of the estimates (~sigma), so the empirical std measures the stopping rule too.
// - sigma sqrt(max K(r,r) / samples) > 0.05 warns (a near-degenerate program): the estimates
//   spread beyond the linearised model's range and trials diverge.
constexpr double kNoiseRefuseAbove = 1.0, kNoiseRefuseBelow = 1e-15;
constexpr double kNoiseWarnAbove = 0.01, kNoiseWarnBelow = 1e-9, kSpreadWarnAbove = 0.05;

void check_noise(double noise, const ModelEvaluation& ev, int samples, const std::string& program) {
  std::ostringstream s;
  s << std::setprecision(3);
  if (noise >= kNoiseRefuseAbove) {
    s << "option --noise: " << noise << " |I| is meaningless for the linearised model (noise as large as the "
      << "measured vector; must be below " << kNoiseRefuseAbove << ")";
    throw UsageError(s.str());
  }
  if (noise < kNoiseRefuseBelow) {
    s << "option --noise: " << noise << " |I| is below the resolution of a double near |I| (must be at least "
      << kNoiseRefuseBelow << ")";
    throw UsageError(s.str());
  }
  auto warn = [](const std::string& what) { std::cerr << "scalcal simulate: warning: " << what << "\n"; };
  if (noise > kNoiseWarnAbove) {
    s << "--noise " << noise << " is above " << kNoiseWarnAbove << ": second-order terms of the modulus (~sigma^2) "
      << "exceed 1% of the noise; the empirical covariance will depart from sigma^2 K";
    warn(s.str());
  } else if (noise < kNoiseWarnBelow) {
    s << "--noise " << noise << " is below " << kNoiseWarnBelow << ": the estimator's stopping tolerance (2.2e-12) "
      << "and rounding are no longer negligible against the noise; the empirical std will be off";
    warn(s.str());
  }
  // One warning per cause; the spread is only worth a line of its own when the noise itself is sane.
  const double spread = noise * std::sqrt(ev.max_diag_K / samples);
  if (spread > kSpreadWarnAbove && noise <= kNoiseWarnAbove) {
    std::ostringstream t;
    t << std::setprecision(3) << program << ": the estimates spread by sigma sqrt(max K(r,r)) = " << spread
      << ", above " << kSpreadWarnAbove << ": outside the linearised model's range; trials may diverge";
    warn(t.str());
  }
  if (ev.condition > kIllConditioned) warn(program + ": " + ill_conditioning(ev));
}

struct Options {
  std::string program, modulus, model = "paper9";
  int trials = 0, samples = 1;
  double noise = 0, bench = 0, size = 1e-3;
  std::uint64_t seed = 1;
  bool json = false;
};

int run(const Options& o) {
  std::vector<Modulus> moduli;
  if (o.modulus.empty()) moduli = {Modulus::norm, Modulus::projection};
  else moduli = {o.modulus == "norm" ? Modulus::norm : Modulus::projection};
  const std::string* program_name = &o.program;
  const int trials = o.trials, samples = o.samples;
  const double noise = o.noise, bench = o.bench, size = o.size;
  const std::uint64_t seed = o.seed;
  const bool json = o.json;

  const Program program = resolve_program(*program_name);
  const ModelKind model = model_of(o.model);
  const ModelEvaluation ev = evaluate(model, program);
  try {
    meter_indices(model);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("simulate: ") + e.what());
  }
  if (!ev.full_rank()) throw InputError(*program_name, 0, rank_deficiency(ev));
  check_noise(noise, ev, samples, *program_name);

  Json all{{"program", *program_name}, {"positions", program.size()}, {"trials", trials},   {"noise", noise},
           {"bench_error_deg", bench},    {"seed", seed},                {"samples", samples}, {"size", size}};
  if (model != ModelKind::paper9) all["model"] = o.model;
  Json results = Json::array();
  if (!json)
    std::cout << "Monte-Carlo calibration: program " << *program_name << " (N = " << program.size() << "), " << trials
              << " trials, noise " << noise << " |I|, bench error " << bench << " deg, " << samples
              << " sample(s) per position, error size " << size << ", seed " << seed
              << (model == ModelKind::paper9 ? "" : ", model " + o.model) << "\n";
  for (const Modulus m : moduli) {
    MonteCarloOptions mc;
    mc.program = program;
    mc.trials = trials;
    mc.noise = noise;
    mc.bench_error_deg = bench;
    mc.modulus = m;
    mc.seed = seed;
    mc.samples = samples;
    mc.size = size;
    std::function<void(int, int)> progress;
    if (progress_enabled())
      progress = [m](int done, int total) {
        std::cerr << "\rsimulate " << modulus_name(m) << ": " << done << "/" << total << std::flush;
        if (done == total) std::cerr << "\n";
      };
    const MonteCarloResult r = run_monte_carlo(mc, progress, model);
    if (json) results.push_back(result_json(r, m));
    else print_result(std::cout, r, m);
  }
  if (json) {
    all["results"] = results;
    print_json(all);
  }
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_text(app, "--program", o->program, "P", {"a catalogue name or a CSV file", "none", kRequired});
  add_integer(app, "--trials", o->trials, 2, 10000000, {"simulated meters calibrated", "trials", kRequired});
  add_number(app, "--noise", o->noise, positive_number(),
             {"noise RMS sigma of each axis of each sample", "|I| (the modulus of the measured vector)", kRequired});
  add_number(app, "--bench-error", o->bench, number_in(0, 30),
             {"every true position is the nominal one tipped by this angle", "degrees"});
  add_choice(app, "--modulus", o->modulus, {"norm", "projection"},
             {"the modulus the estimator fits", "none", "both, one after the other"});
  add_model(app, o->model);
  add_seed(app, o->seed);
  add_integer(app, "--samples", o->samples, 1, 100000, {"samples per position", "samples"});
  add_number(app, "--size", o->size, number_in(0, 0.2),
             {"scale of the simulated meter's errors", "relative (bias in |I|, angles in radians)"});
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"simulate", kUsage,
                        "Monte-Carlo calibration of simulated meters: empirical covariance against sigma^2 K, "
                        "bias of the estimator, effect of bench errors on each modulus",
                        41, setup});

}  // namespace
}  // namespace scalcal::cli
