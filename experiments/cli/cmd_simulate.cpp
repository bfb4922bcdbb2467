// `scalcal simulate --program P --trials T --noise SIGMA [--bench-error DEG] [--modulus ...] [--model NAME]
// [--seed S] [--samples K] [--size A] [--out FILE] [--json]`: Monte-Carlo calibration of simulated meters
// (commands/calibration/simulate.hpp), printed as a table per modulus; with --log FILE or --bench-file FILE a
// rehearsal instead (commands/calibration/rehearsal.hpp): the files, and the true parameters in --truth FILE.
#include <cmath>
#include <iomanip>
#include <iostream>

#include "commands/calibration/simulate.hpp"
#include "commands/core/common_options.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

using commands::shortest_text;

void print_result(std::ostream& out, const MonteCarloResult& r, Modulus m) {
  out << "\nmodulus " << commands::modulus_name(m) << ": " << r.converged << " converged trials, "
      << std::setprecision(3) << r.mean_iterations << " iterations on average\n";
  out << "  parameter        truth         bias   bias/se  lin. error   emp. std  theor. std   ratio\n";
  for (int k = 0; k < static_cast<int>(r.truth.size()); ++k) {
    const double th = std::sqrt(r.theoretical_cov(k, k));
    const double emp = std::sqrt(r.empirical_cov(k, k));
    const double se_mean = emp / std::sqrt(std::max(1, r.converged));
    out << "  " << std::left << std::setw(11) << r.names[static_cast<std::size_t>(k)] << std::right
        << std::setprecision(4) << std::setw(12) << r.truth(k) << std::setw(13) << r.mean(k) - r.truth(k)
        << std::setw(10) << std::setprecision(2) << (r.mean(k) - r.truth(k)) / se_mean << std::setprecision(4)
        << std::setw(12) << r.noise_free(k) - r.truth(k) << std::setw(11) << emp << std::setw(12) << th << std::setw(8)
        << std::setprecision(3) << emp / th << "\n";
  }
  out << "  theta (sqrt(N max var)/sigma)  empirical / theoretical:";
  for (int q = 0; q < 4; ++q)
    if (!std::isnan(r.theta_theoretical(q)))
      out << "  " << kGroupNames[static_cast<std::size_t>(q)] << " " << std::setprecision(4) << r.theta_empirical(q)
          << " / " << r.theta_theoretical(q);
  out << "\n  sampling error of an empirical std: " << std::setprecision(2) << 100 * r.std_sampling_error()
      << "% (1 sigma); max normalised covariance difference " << std::setprecision(3)
      << r.max_normalised_cov_difference() << "; estimated noise / sigma " << std::setprecision(4) << r.mean_noise_ratio
      << "\n";
}

// --out: the table print_result shows, as CSV, one row per modulus and parameter (standard_error:
// of the mean estimate, the bias's scale).
void write_table(std::ostream& out, const commands::SimulateResult& r) {
  out << "modulus,parameter,truth,bias,standard_error,linear_error,empirical_std,theoretical_std\n";
  for (const auto& [m, c] : r.results)
    for (int k = 0; k < static_cast<int>(c.truth.size()); ++k) {
      const double emp = std::sqrt(c.empirical_cov(k, k));
      out << commands::modulus_name(m) << ',' << c.names[static_cast<std::size_t>(k)] << ','
          << shortest_text(c.truth(k)) << ',' << shortest_text(c.mean(k) - c.truth(k)) << ','
          << shortest_text(emp / std::sqrt(std::max(1, c.converged))) << ','
          << shortest_text(c.noise_free(k) - c.truth(k)) << ',' << shortest_text(emp) << ','
          << shortest_text(std::sqrt(c.theoretical_cov(k, k))) << '\n';
    }
}

// --log / --bench-file: the files, and one line (or the truth as JSON) on stdout.
int rehearse(const commands::Values& v, const commands::RehearsalRequest& q) {
  const commands::RehearsalResult r = commands::rehearse(q);
  print_warnings("simulate", r.warnings);
  if (q.grouped)
    write_output_file(v.text("--bench-file"),
                      [&](std::ostream& out) { commands::write_bench_file(out, r, v.text("--bench-file")); });
  else
    write_output_file(v.text("--log"), [&](std::ostream& out) {
      commands::write_raw_log(out, r, v.text("--format") == "text", v.text("--log"));
    });
  const commands::Json truth = commands::truth_json(r);
  if (v.given("--truth")) write_output_file(v.text("--truth"), [&](std::ostream& out) { write_json(out, truth); });
  if (v.flag("--json")) {
    print_json(truth);
    return 0;
  }
  std::cout << "rehearsal of " << q.name << ": " << q.program.size() << " positions, " << r.t.size() << " rows ("
            << std::setprecision(4) << r.t.back() + 1 / q.rate_hz << " s at " << q.rate_hz << " Hz), noise " << q.noise
            << " |I|, seed " << q.seed << " -> " << (q.grouped ? v.text("--bench-file") : v.text("--log"))
            << (v.given("--truth") ? ", true parameters -> " + v.text("--truth") : std::string()) << "\n";
  return 0;
}

// --instrument gyro --log: the gyro's log (and the accelerometer's), the truth, one line on stdout.
int rehearse_gyro(const commands::Values& v, const commands::GyroRehearsalRequest& q) {
  const commands::GyroRehearsalResult r = commands::rehearse_gyro(q);
  print_warnings("simulate", r.warnings);
  write_output_file(v.text("--log"), [&](std::ostream& out) { commands::write_gyro_log(out, r.log.log, r.log.rate); });
  if (r.accelerometer_log)
    write_output_file(v.text("--accelerometer"),
                      [&](std::ostream& out) { commands::write_gyro_log(out, *r.accelerometer_log, {}); });
  const commands::Json truth = commands::gyro_truth_json(r);
  if (v.given("--truth")) write_output_file(v.text("--truth"), [&](std::ostream& out) { write_json(out, truth); });
  if (v.flag("--json")) {
    print_json(truth);
    return 0;
  }
  const RawLog& log = r.log.log;
  std::cout << "gyro rehearsal of " << q.name << " (" << q.method << "): " << q.program.size() << " positions, "
            << log.size() << " rows (" << std::setprecision(4) << log.t.back() + 1 / q.rate_hz << " s at " << q.rate_hz
            << " Hz), noise " << q.noise << " |I|, seed " << q.seed << " -> " << v.text("--log")
            << (r.accelerometer_log ? ", accelerometer -> " + v.text("--accelerometer") : std::string())
            << (v.given("--truth") ? ", true parameters -> " + v.text("--truth") : std::string()) << "\n";
  return 0;
}

// --model BASE+Tk --log: the thermal log and its truth, one line on stdout.
int rehearse_thermal(const commands::Values& v, const ThermalRehearsalRequest& q) {
  const ThermalRehearsal r = scalcal::rehearse_thermal(q);
  write_output_file(v.text("--log"), [&](std::ostream& out) { commands::write_thermal_log(out, q, r); });
  const commands::Json truth = commands::thermal_truth_json(q, r);
  if (v.given("--truth")) write_output_file(v.text("--truth"), [&](std::ostream& out) { write_json(out, truth); });
  if (v.flag("--json")) {
    print_json(truth);
    return 0;
  }
  std::cout << "thermal rehearsal of " << v.text("--program") << " under " << q.model.name() << ": " << q.program.size()
            << (q.ramp_c_per_min > 0
                    ? " positions over and over on a ramp of " + commands::shortest_text(q.ramp_c_per_min) +
                          " degC/min from " + q.range.text() + " degC, "
                    : std::string(" rows of the program, "))
            << r.t.size() << " samples (" << std::setprecision(4) << r.t.back() + 1 / q.rate_hz << " s at " << q.rate_hz
            << " Hz), noise " << q.noise << " |I|, seed " << q.seed << " -> " << v.text("--log")
            << (v.given("--truth") ? ", true parameters -> " + v.text("--truth") : std::string()) << "\n";
  return 0;
}

int run(const commands::Values& v) {
  const commands::SimulateRequest q = commands::simulate_request(v);
  if (q.thermal_rehearsal) return rehearse_thermal(v, *q.thermal_rehearsal);
  if (q.rehearsal) return rehearse(v, *q.rehearsal);
  if (q.gyro_rehearsal) return rehearse_gyro(v, *q.gyro_rehearsal);
  const bool json = v.flag("--json");
  const auto r = commands::simulate(q, terminal_progress("simulate"));
  print_warnings("simulate", r.warnings);
  if (v.given("--out")) write_output_file(v.text("--out"), [&](std::ostream& out) { write_table(out, r); });
  if (!json)
    std::cout << "Monte-Carlo calibration: program " << q.name << " (N = " << q.program.size() << "), " << q.trials
              << " trials, noise " << q.noise << " |I|, bench error " << q.bench_error_deg << " deg, " << q.samples
              << " sample(s) per position, error size " << q.size << ", seed " << q.seed
              << (is_default_model(q.model) ? "" : ", model " + std::string(model_name(q.model))) << "\n";
  if (json)
    print_json(commands::to_json(r));
  else
    for (const auto& [m, result] : r.results) print_result(std::cout, result, m);
  return 0;
}

const Registration reg(commands::simulate_table(), run);

}  // namespace
}  // namespace scalcal::cli
