// `scalcal simulate` (simulate.hpp).
#include "commands/calibration/simulate.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "commands/core/region_request.hpp"
#include "commands/core/usage_error.hpp"
#include "commands/core/work_bound.hpp"
#include "numeric/calibration/model_calibration.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {
namespace {

// The range of --noise sigma (relative to |I|) where the Monte-Carlo answers the question it is
// asked (docs: `simulate`):
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

void check_noise(const SimulateRequest& q, const ModelEvaluation& ev, Warnings& warnings) {
  std::ostringstream s;
  s << std::setprecision(3);
  const double noise = q.noise;
  if (noise >= kNoiseRefuseAbove) {
    s << words("option {noise}: ") << noise << " |I| is meaningless for the linearised model (noise as large as the "
      << "measured vector; must be below " << kNoiseRefuseAbove << ")";
    throw UsageError(s.str());
  }
  if (noise < kNoiseRefuseBelow) {
    s << words("option {noise}: ") << noise << " |I| is below the resolution of a double near |I| (must be at least "
      << kNoiseRefuseBelow << ")";
    throw UsageError(s.str());
  }
  if (noise > kNoiseWarnAbove) {
    s << words("{noise} ") << noise << " is above " << kNoiseWarnAbove
      << ": second-order terms of the modulus (~sigma^2) "
      << "exceed 1% of the noise; the empirical covariance will depart from sigma^2 K";
    warnings.push_back({"", s.str()});
  } else if (noise < kNoiseWarnBelow) {
    s << words("{noise} ") << noise << " is below " << kNoiseWarnBelow
      << ": the estimator's stopping tolerance (2.2e-12) "
      << "and rounding are no longer negligible against the noise; the empirical std will be off";
    warnings.push_back({"", s.str()});
  }
  // One warning per cause; the spread is only worth a line of its own when the noise itself is sane.
  const double spread = noise * std::sqrt(ev.raw(CriterionKind::S) / q.samples);
  if (spread > kSpreadWarnAbove && noise <= kNoiseWarnAbove) {
    std::ostringstream t;
    t << std::setprecision(3) << "the estimates spread by sigma sqrt(max K(r,r)) = " << spread << ", above "
      << kSpreadWarnAbove << ": outside the linearised model's range; trials may diverge";
    warnings.push_back({q.name, t.str()});
  }
  if (ev.condition > kIllConditioned) warnings.push_back({q.name, ill_conditioning(ev)});
}

}  // namespace

const char* modulus_name(Modulus m) { return m == Modulus::norm ? "norm" : "projection"; }

namespace {

// The rehearsal writes files: the CLI and the Python module both write them (a rehearsal's options
// are Python arguments too: simulate(log=..., truth=...)).
Option rehearsal(Option o) {
  o.cli_only = false;
  return o;
}

}  // namespace

const CommandTable& simulate_table() {
  Option program = text_option("--program", "P", "a catalogue name or a CSV file", "none", kRequired);
  program.fallback = "";
  program.fallback_text = words("required, unless {tumble}");
  program.takes_positions = true;
  Option modulus = choice_option("--modulus", {"norm", "projection"}, "the modulus the estimator fits", "");
  modulus.fallback_text = "both, one after the other";
  Option log = out_option(
      "rehearsal: write the raw log (t,ix,iy,iz) a meter would give on the program run in its "
      "order, motion included (no Monte-Carlo)");
  log.name = "--log";
  log.cli_only = false;
  Option bench_file = out_option("rehearsal: write the grouped bench file (position,x,y,z,ix,iy,iz) instead");
  bench_file.name = "--bench-file";
  bench_file.cli_only = false;
  Option truth =
      out_option(words("with {log} or {bench-file}: write the meter's true parameters as JSON (calibrate "
                       "{json}'s keys and units)"));
  truth.name = "--truth";
  truth.cli_only = false;
  Option accelerometer_log = out_option(  // an output: another output's file is refused (check_distinct_outputs)
      words(
          "rehearsal with {instrument gyro}: hand rotations; write the accelerometer's log (same rows as {log}) here"),
      "FILE");
  accelerometer_log.name = "--accelerometer";
  accelerometer_log.cli_only = false;
  static const CommandTable table{
      "simulate",
      "Monte-Carlo calibration of simulated meters (empirical covariance against sigma^2 K, bias, bench errors), or "
      "a rehearsal log of a program with its true parameters",
      41,
      {program,
       named(integer_option("--trials", 2, 10000000, "simulated meters calibrated", "trials", "0",
                            words("required, unless {log} or {bench-file}")),
             "T"),
       positive_option("--noise", "noise RMS sigma of each axis of each sample",
                       "|I| (the modulus of the measured vector)", kRequired),
       number_option("--bench-error", 0, 30, "every true position is the nominal one tipped by this angle", "degrees",
                     "0"),
       modulus,
       model_or_thermal_option(),
       temperature_option(),
       seed_option(),
       named(integer_option("--samples", 1, 100000, "samples per position", "samples", "1"), "K"),
       number_option("--size", 0, 0.2, "scale of the simulated meter's errors",
                     "relative (bias in |I|, angles in radians)", "0.001"),
       out_option("write the Monte-Carlo table as CSV, one row per modulus and parameter"),
       log,
       bench_file,
       truth,
       rehearsal(text_option("--meter", "FILE",
                             words("rehearsal: the meter's parameters (bias, scale_deviation, "
                                   "nonorthogonality as calibrate {json} writes them) instead of "
                                   "random ones"),
                             "file path")),
       rehearsal(positive_option("--rate", "rehearsal: samples per second", "Hz", "100")),
       rehearsal(positive_option("--dwell", "rehearsal: seconds at rest on each position", "seconds", "5")),
       rehearsal(number_option("--ramp", 0, 100,
                               "thermal rehearsal: the temperature climbs from T1 to T2 at this rate while the "
                               "program's positions (x,y,z) run over and over (0: the program's set-points, t_c)",
                               "degC per minute", "0")),
       rehearsal(number_option("--still", 0, 3600,
                               words("rehearsal: seconds at rest on the first position (calibrate's {still})"),
                               "seconds", "30")),
       rehearsal(positive_option("--magnitude", "rehearsal: |I| in the log's units", "log units", "1")),
       rehearsal(choice_option("--format", {"csv", "text"},
                               "rehearsal: the raw log as CSV with a header, or text t ix iy iz (IMU-TK's reader: "
                               "numbers only)",
                               "csv")),
       rehearsal(
           number_option("--tumble", 0, 86400,
                         words("rehearsal: a tumbling log of this many seconds, the meter turned continuously (through "
                               "the program's positions, or random directions without {program}) and never still"),
                         "seconds", "0")),
       rehearsal(choice_option(
           "--instrument", {"mag", "accel", "gyro"},
           words("rehearsal: the meter. With {tumble} a magnetometer (the field keeps its modulus) or an "
                 "accelerometer (the motion adds 5 % of |I| of acceleration); gyro (no {tumble}): the "
                 "program's positions are a rate table's axes (signed by the turn), known turns' axes "
                 "({turn-angle}) or gravity's directions at the poses of hand rotations ({accelerometer})"),
           "mag")),
       rehearsal(named(integer_option("--disturbances", 0, 100,
                                      words("rehearsal {tumble}: disturbed stretches of 2 s (a field of up to 0.3 |I| "
                                            "passing), at random times"),
                                      "stretches", "0"),
                       "K")),
       rehearsal(number_option("--turn-angle", -3600, 3600,
                               words("rehearsal with {instrument gyro}: known turns of this angle about each position "
                                     "instead of a rate table"),
                               "degrees", "")),
       rehearsal(accelerometer_log),
       rehearsal(
           number_option("--latitude", -90, 90,
                         words("rehearsal with {instrument gyro} on a rate table: add the Earth's rate (the table's "
                               "axis vertical)"),
                         "degrees", "")),
       json_option("print one JSON object")}};
  return table;
}

namespace {

// --instrument gyro: a gyro's rehearsal (a raw log only).
void read_gyro_rehearsal(const Values& v, SimulateRequest& q) {
  if (!v.given("--log"))
    throw UsageError(words("{instrument gyro} writes a raw log: give {log FILE} (not {bench-file})"));
  for (const char* o : {"--meter", "--still", "--format", "--tumble", "--disturbances"})
    if (v.given(o))
      throw UsageError(option_word(o) + words(" belongs to the accelerometer's rehearsal, not {instrument gyro}"));
  if (v.given("--turn-angle") && v.given("--accelerometer"))
    throw UsageError(words("give {turn-angle} (known turns) or {accelerometer} (hand rotations), not both"));
  if (v.given("--latitude") && (v.given("--turn-angle") || v.given("--accelerometer")))
    throw UsageError(words("{latitude} belongs to a rate table (no {turn-angle}, no {accelerometer})"));
  GyroRehearsalRequest g;
  g.name = q.name;
  g.program = q.program;
  g.method = v.given("--turn-angle") ? "known_turns" : v.given("--accelerometer") ? "hand_rotations" : "rate_table";
  g.rate_hz = v.number("--rate");
  g.dwell_s = v.number("--dwell");
  g.noise = v.number("--noise");
  g.magnitude = v.number("--magnitude");
  if (v.given("--turn-angle")) g.turn_angle_deg = v.number("--turn-angle");
  if (g.method == "known_turns" && g.turn_angle_deg == 0) throw UsageError(words("{turn-angle} must not be 0"));
  if (v.given("--latitude")) g.latitude_deg = v.number("--latitude");
  g.size = v.number("--size");
  g.seed = static_cast<std::uint64_t>(v.integer("--seed"));
  if (g.noise >= kNoiseRefuseAbove)
    throw UsageError(words("option {noise}: must be below 1 |I| (noise as large as the measured vector)"));
  check_rehearsal_rate(g.rate_hz);
  // Seconds per position at most: a rest, the spin-up and stop (or a hand's move) and the segment, and a known
  // turn's own duration (a quarter turn a second, gyro_rehearsal.cpp).
  const double turn_s = g.method == "known_turns" ? std::abs(g.turn_angle_deg) / 90 : 0;
  if (g.rate_hz * (2 * g.dwell_s + 4 + turn_s) * static_cast<double>(g.program.size()) > kMaxRehearsalRows)
    throw UsageError(words("{rate} x {dwell} x positions asks for more than 2e7 rows"));
  q.gyro_rehearsal = std::move(g);
}

// --log or --bench-file: the rehearsal's request; the Monte-Carlo's options are refused there, and
// the rehearsal's without it.
void read_rehearsal(const Values& v, SimulateRequest& q) {
  const bool rehearsal = v.given("--log") || v.given("--bench-file");
  const char* monte_carlo[] = {"--trials", "--bench-error", "--modulus", "--samples", "--model", "--out"};
  const char* own[] = {"--truth",      "--meter",         "--rate",    "--dwell",      "--still",
                       "--magnitude",  "--format",        "--tumble",  "--instrument", "--disturbances",
                       "--turn-angle", "--accelerometer", "--latitude"};
  if (!rehearsal) {
    for (const char* o : own)
      if (v.given(o))
        throw UsageError(option_word(o) + words(" belongs to a rehearsal ({log FILE} or {bench-file FILE})"));
    if (!v.given("--trials")) throw UsageError(words("{trials T} is required (or {log FILE} for a rehearsal)"));
    return;
  }
  if (v.given("--log") && v.given("--bench-file")) throw UsageError(words("give {log} or {bench-file}, not both"));
  for (const char* o : monte_carlo)
    if (v.given(o)) throw UsageError(option_word(o) + " belongs to the Monte-Carlo, not to a rehearsal");
  if (v.given("--format") && v.given("--bench-file")) throw UsageError(words("{format} is the raw log's ({log})"));
  if (v.text("--instrument") == "gyro") {
    read_gyro_rehearsal(v, q);
    return;
  }
  for (const char* o : {"--turn-angle", "--accelerometer", "--latitude"})
    if (v.given(o)) throw UsageError(option_word(o) + words(" belongs to {instrument gyro}"));
  RehearsalRequest r;
  r.name = q.name;
  r.program = q.program;
  Warnings unused;
  if (!v.program && v.given("--program")) r.region = regions_for({}, q.name, unused);
  r.grouped = v.given("--bench-file");
  r.rate_hz = v.number("--rate");
  r.dwell_s = v.number("--dwell");
  r.still_s = r.grouped ? 0 : v.number("--still");
  r.noise = v.number("--noise");
  r.magnitude = v.number("--magnitude");
  r.size = v.number("--size");
  r.meter_file = v.text("--meter");
  r.seed = static_cast<std::uint64_t>(v.integer("--seed"));
  r.tumble_s = v.number("--tumble");
  r.accelerometer = v.text("--instrument") == "accel";
  r.disturbances = static_cast<int>(v.integer("--disturbances"));
  if (r.tumble_s == 0)
    for (const char* o : {"--instrument", "--disturbances"})
      if (v.given(o)) throw UsageError(option_word(o) + words(" belongs to a tumbling rehearsal ({tumble SECONDS})"));
  if (r.tumble_s > 0 && r.grouped) throw UsageError(words("{tumble} writes a raw log ({log}), not a bench file"));
  if (r.tumble_s > 0 && r.rate_hz * r.tumble_s > 2e7)
    throw UsageError(words("{rate} x {tumble} asks for more than 2e7 rows"));
  if (r.noise >= kNoiseRefuseAbove)
    throw UsageError(words("option {noise}: must be below 1 |I| (noise as large as the measured vector)"));
  check_rehearsal_size(r);  // before any work: the rows, moves included
  q.rehearsal = std::move(r);
}

}  // namespace

SimulateRequest simulate_request(const Values& v) {
  SimulateRequest q;
  q.name = v.text("--program");
  q.thermal_rehearsal = thermal_rehearsal_request(v);
  if (q.thermal_rehearsal) return q;
  if (v.given("--program") || v.program)
    q.program = program_of(v, "--program");
  else if (!(v.given("--tumble") && v.number("--tumble") > 0))
    throw UsageError(words("{program P} is required (unless {log} with {tumble SECONDS})"));
  else
    q.name = "a random tumble";
  read_rehearsal(v, q);
  if (q.rehearsal || q.gyro_rehearsal) return q;
  q.trials = static_cast<int>(v.integer("--trials"));
  q.noise = v.number("--noise");
  q.bench_error_deg = v.number("--bench-error");
  if (v.given("--modulus")) q.moduli = {v.text("--modulus") == "norm" ? Modulus::norm : Modulus::projection};
  q.model = model_of(v);
  q.seed = static_cast<std::uint64_t>(v.integer("--seed"));
  q.samples = static_cast<int>(v.integer("--samples"));
  q.size = v.number("--size");
  return q;
}

SimulateResult simulate(const SimulateRequest& q, const Progress& progress) {
  SimulateResult r;
  r.request = q;
  const ModelEvaluation ev = evaluate(q.model, q.program);
  try {
    meter_slots(q.model);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("simulate: ") + e.what());
  }
  if (!ev.full_rank()) throw InputError(q.name, 0, rank_deficiency(ev));
  check_work(words("{trials} ") + std::to_string(q.trials) + " of " + std::to_string(q.program.size()) +
                 words(" positions with {samples} ") + std::to_string(q.samples),
             monte_carlo_work(static_cast<long long>(q.trials) * static_cast<long long>(q.moduli.size()),
                              q.program.size(), q.samples, model_parameters(q.model)),
             words("fewer {trials} or {samples}"));
  check_noise(q, ev, r.warnings);
  for (const Modulus m : q.moduli) {
    MonteCarloOptions mc;
    mc.program = q.program;
    mc.trials = q.trials;
    mc.noise = q.noise;
    mc.bench_error_deg = q.bench_error_deg;
    mc.modulus = m;
    mc.seed = q.seed;
    mc.samples = q.samples;
    mc.size = q.size;
    std::function<void(int, int)> step;
    if (progress)
      step = [&](int done, int total) { progress(std::string("simulate ") + modulus_name(m), done, total); };
    r.results.emplace_back(m, run_monte_carlo(mc, step, q.model));
  }
  return r;
}

Json to_json(const SimulateResult& result) {
  const SimulateRequest& q = result.request;
  Json all{{"program", q.name},
           {"positions", q.program.size()},
           {"trials", q.trials},
           {"noise", q.noise},
           {"bench_error_deg", q.bench_error_deg},
           {"seed", q.seed},
           {"samples", q.samples},
           {"size", q.size}};
  if (!is_default_model(q.model)) all["model"] = std::string(model_name(q.model));
  Json results = Json::array();
  for (const auto& [m, r] : result.results) {
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
    for (int g = 0; g < 4; ++g) {
      if (std::isnan(r.theta_theoretical(g))) continue;  // a group the model lacks
      te[std::string(kGroupNames[static_cast<std::size_t>(g)])] = r.theta_empirical(g);
      tt[std::string(kGroupNames[static_cast<std::size_t>(g)])] = r.theta_theoretical(g);
    }
    results.push_back(Json{{"modulus", modulus_name(m)},
                           {"converged_trials", r.converged},
                           {"mean_iterations", r.mean_iterations},
                           {"parameters", params},
                           {"theta_empirical", te},
                           {"theta_theoretical", tt},
                           {"std_sampling_error", r.std_sampling_error()},
                           {"max_normalised_cov_difference", r.max_normalised_cov_difference()},
                           {"mean_noise_ratio", r.mean_noise_ratio}});
  }
  all["results"] = results;
  return all;
}

}  // namespace scalcal::commands
