// `scalcal simulate` as a function: Monte-Carlo calibration of simulated meters on a program, the
// empirical covariance of the estimates against sigma^2 K, the estimator's bias, and the effect of
// bench errors, for one or both moduli.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "commands/calibration/gyro_rehearsal.hpp"
#include "commands/calibration/rehearsal.hpp"
#include "commands/calibration/thermal_rehearsal.hpp"
#include "commands/core/common_options.hpp"
#include "commands/core/json.hpp"
#include "commands/core/progress.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"
#include "numeric/calibration/monte_carlo.hpp"

namespace scalcal::commands {

struct SimulateRequest {
  std::string name;  // the program's name in messages
  Program program;
  int trials = 0, samples = 1;
  double noise = 0, bench_error_deg = 0, size = 1e-3;
  std::vector<Modulus> moduli{Modulus::norm, Modulus::projection};
  ModelKind model = ModelKind::paper9;
  std::uint64_t seed = 1;
  // --log / --bench-file: a rehearsal (commands/calibration/rehearsal.hpp) instead of the Monte-Carlo.
  std::optional<RehearsalRequest> rehearsal;
  // --instrument gyro --log: a gyro's rehearsal (commands/calibration/gyro_rehearsal.hpp).
  std::optional<GyroRehearsalRequest> gyro_rehearsal;
  // --model BASE+Tk --temperature T1..T2 --log: a thermal rehearsal (commands/calibration/thermal_rehearsal.hpp).
  std::optional<ThermalRehearsalRequest> thermal_rehearsal;
};

struct SimulateResult {
  SimulateRequest request;
  std::vector<std::pair<Modulus, MonteCarloResult>> results;  // one per modulus, in the request's order
  Warnings warnings;
};

// --program P --trials T --noise SIGMA [--bench-error DEG] [--modulus norm|projection] [--model NAME]
// [--seed S] [--samples K] [--size A] [--json], or for a rehearsal --program P --noise SIGMA
// --log FILE|--bench-file FILE [--truth FILE] [--meter FILE] [--rate HZ] [--dwell S] [--still S]
// [--magnitude M] [--format csv|text] [--seed S] [--size A]; --instrument gyro --log FILE [--turn-angle DEG |
// --accelerometer FILE] [--latitude DEG] for a gyro's
const CommandTable& simulate_table();
SimulateRequest simulate_request(const Values& values);

// Throws UsageError for a noise outside what the linearised model answers (>= 1 |I| or below a
// double's resolution) or a model the simulator does not take, InputError for a rank-deficient
// program; warns for noise where the answer degrades.
SimulateResult simulate(const SimulateRequest& request, const Progress& progress = {});

Json to_json(const SimulateResult& result);

const char* modulus_name(Modulus m);  // "norm", "projection"

}  // namespace scalcal::commands
