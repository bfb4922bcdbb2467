// `scalcal simulate --program P --trials T --noise SIGMA [--bench-error DEG] [--modulus ...]
// [--seed S] [--json]`: Monte-Carlo calibration of simulated meters, the empirical covariance of
// the estimates against sigma^2 K, the estimator's bias, and the effect of bench errors.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <vector>

#include "experiments/command.hpp"
#include "experiments/json.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/calibration/monte_carlo.hpp"
#include "numeric/model/paper9.hpp"

namespace scalcal::cli {
namespace {

constexpr const char* kUsage =
    "simulate --program P --trials T --noise SIGMA [--bench-error DEG] [--modulus norm|projection] [--seed S] "
    "[--samples K] [--size A] [--json]";

const char* modulus_name(Modulus m) { return m == Modulus::norm ? "norm" : "projection"; }

Json result_json(const MonteCarloResult& r, Modulus m) {
  Json j = Json::object();
  j.set("modulus", modulus_name(m));
  j.set("converged_trials", r.converged);
  j.set("mean_iterations", r.mean_iterations);
  Json params = Json::array();
  for (int k = 0; k < 9; ++k) {
    const double th = std::sqrt(r.theoretical_cov(k, k));
    const double se_mean = std::sqrt(r.empirical_cov(k, k) / std::max(1, r.converged));
    Json p = Json::object();
    p.set("name", std::string(kParameterNames[k]));
    p.set("truth", r.truth(k));
    p.set("mean", r.mean(k));
    p.set("bias", r.mean(k) - r.truth(k));
    p.set("bias_in_std_errors", (r.mean(k) - r.truth(k)) / se_mean);
    p.set("noise_free", r.noise_free(k));
    p.set("linearisation_error", r.noise_free(k) - r.truth(k));
    p.set("noise_bias_in_std_errors", (r.mean(k) - r.noise_free(k)) / se_mean);
    p.set("empirical_std", std::sqrt(r.empirical_cov(k, k)));
    p.set("theoretical_std", th);
    p.set("std_ratio", std::sqrt(r.empirical_cov(k, k)) / th);
    params.push(p);
  }
  j.set("parameters", params);
  Json te = Json::object(), tt = Json::object();
  for (int q = 0; q < 3; ++q) {
    te.set(std::string(kGroupNames[q]), r.theta_empirical(q));
    tt.set(std::string(kGroupNames[q]), r.theta_theoretical(q));
  }
  j.set("theta_empirical", te);
  j.set("theta_theoretical", tt);
  j.set("std_sampling_error", r.std_sampling_error());
  j.set("max_normalised_cov_difference", r.max_normalised_cov_difference());
  j.set("mean_noise_ratio", r.mean_noise_ratio);
  return j;
}

void print_result(std::ostream& out, const MonteCarloResult& r, Modulus m) {
  out << "\nmodulus " << modulus_name(m) << ": " << r.converged << " converged trials, "
      << std::setprecision(3) << r.mean_iterations << " iterations on average\n";
  out << "  parameter        truth         bias   bias/se  lin. error   emp. std  theor. std   ratio\n";
  for (int k = 0; k < 9; ++k) {
    const double th = std::sqrt(r.theoretical_cov(k, k));
    const double emp = std::sqrt(r.empirical_cov(k, k));
    const double se_mean = emp / std::sqrt(std::max(1, r.converged));
    out << "  " << std::left << std::setw(11) << kParameterNames[k] << std::right << std::setprecision(4)
        << std::setw(12) << r.truth(k) << std::setw(13) << r.mean(k) - r.truth(k) << std::setw(10)
        << std::setprecision(2) << (r.mean(k) - r.truth(k)) / se_mean << std::setprecision(4) << std::setw(12)
        << r.noise_free(k) - r.truth(k) << std::setw(11) << emp
        << std::setw(12) << th << std::setw(8) << std::setprecision(3) << emp / th << "\n";
  }
  out << "  theta (sqrt(N max var)/sigma)  empirical / theoretical:";
  for (int q = 0; q < 3; ++q)
    out << "  " << kGroupNames[q] << " " << std::setprecision(4) << r.theta_empirical(q) << " / "
        << r.theta_theoretical(q);
  out << "\n  sampling error of an empirical std: " << std::setprecision(2) << 100 * r.std_sampling_error()
      << "% (1 sigma); max normalised covariance difference " << std::setprecision(3)
      << r.max_normalised_cov_difference() << "; estimated noise / sigma " << std::setprecision(4)
      << r.mean_noise_ratio << "\n";
}

int run(Args& args) {
  const bool json = args.flag("json");
  const auto program_name = args.value("program");
  const int trials = static_cast<int>(args.integer("trials", -1, 2, 10000000));
  const double noise = args.real("noise", -1.0);
  const double bench = args.real("bench-error", 0.0);
  const auto modulus_text = args.value("modulus");
  const auto seed = static_cast<std::uint64_t>(args.integer("seed", 1, 0, (1LL << 62)));
  const int samples = static_cast<int>(args.integer("samples", 1, 1, 100000));
  const double size = args.real("size", 1e-3);
  if (!args.positionals().empty()) throw UsageError("unexpected argument '" + args.positionals().front() + "'");
  if (!program_name) throw UsageError("missing --program P");
  if (trials < 0) throw UsageError("missing --trials T");
  if (noise < 0) throw UsageError(args.value("noise") ? "option --noise must be positive" : "missing --noise SIGMA");
  if (!(noise > 0)) throw UsageError("option --noise must be positive");
  if (bench < 0 || bench > 30) throw UsageError("option --bench-error must be in 0..30 degrees");
  if (size < 0 || size > 0.2) throw UsageError("option --size must be in 0..0.2");
  std::vector<Modulus> moduli;
  if (!modulus_text) moduli = {Modulus::norm, Modulus::projection};
  else if (*modulus_text == "norm") moduli = {Modulus::norm};
  else if (*modulus_text == "projection") moduli = {Modulus::projection};
  else throw UsageError("option --modulus takes norm or projection, got '" + *modulus_text + "'");

  const Program program = resolve_program(*program_name);
  const Evaluation ev = evaluate(program);
  if (!ev.full_rank()) throw InputError(*program_name, 0, "rank-deficient program: rank " + std::to_string(ev.rank) + " of 9");

  Json all = Json::object();
  all.set("program", *program_name);
  all.set("positions", program.size());
  all.set("trials", trials);
  all.set("noise", noise);
  all.set("bench_error_deg", bench);
  all.set("seed", static_cast<long long>(seed));
  all.set("samples", samples);
  all.set("size", size);
  Json results = Json::array();
  if (!json)
    std::cout << "Monte-Carlo calibration: program " << *program_name << " (N = " << program.size() << "), " << trials
              << " trials, noise " << noise << " |I|, bench error " << bench << " deg, " << samples
              << " sample(s) per position, error size " << size << ", seed " << seed << "\n";
  for (const Modulus m : moduli) {
    MonteCarloOptions o;
    o.program = program;
    o.trials = trials;
    o.noise = noise;
    o.bench_error_deg = bench;
    o.modulus = m;
    o.seed = seed;
    o.samples = samples;
    o.size = size;
    std::function<void(int, int)> progress;
    if (progress_enabled())
      progress = [m](int done, int total) {
        std::cerr << "\rsimulate " << modulus_name(m) << ": " << done << "/" << total << std::flush;
        if (done == total) std::cerr << "\n";
      };
    const MonteCarloResult r = run_monte_carlo(o, progress);
    if (json) results.push(result_json(r, m));
    else print_result(std::cout, r, m);
  }
  if (json) {
    all.set("results", results);
    all.dump(std::cout);
    std::cout << "\n";
  }
  return 0;
}

const Registration reg({"simulate", kUsage,
                        "Monte-Carlo calibration of simulated meters: empirical covariance against sigma^2 K, "
                        "bias of the estimator, effect of bench errors on each modulus",
                        41, run});

}  // namespace
}  // namespace scalcal::cli
