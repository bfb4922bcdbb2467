// `scalcal optimize --model BASE+Tk --temperature T1..T2 --positions N`: a thermal program as Theorem 25
// builds one, a sphere program times the interval's optimal set-points: N = N_s x n, each of the N_s
// positions repeated at the set-points with counts rounded from their weights to n (Pukelsheim and
// Rieder's efficient rounding), n chosen for the rounding's efficiency (ties: the largest N_s). It is the
// limit's design exactly where the sphere program attains its limit and the weights are multiples of
// 1/n (D: n = k + 1); the report says how close it comes.
#pragma once
#include <optional>
#include <vector>

#include "commands/design/optimize.hpp"
#include "commands/design/thermal_evaluate.hpp"

namespace scalcal::commands {

struct ThermalOptimizeResult {
  CriterionKind criterion = CriterionKind::D;
  int positions = 0;             // N
  int sphere_positions = 0;      // N_s
  IntervalDesign design;         // the set-points and their optimal weights
  std::vector<int> counts;       // repeats at each set-point, summing to n = N / N_s
  OptimizeResult sphere;         // the sphere program's synthesis
  ThermalEvaluation evaluation;  // the product program, judged against the thermal limits
  Warnings warnings;
};

// Throws UsageError when N has no split into N_s >= the base's parameters times n >= the set-points.
ThermalOptimizeResult thermal_optimize(const OptimizeRequest& request, const ThermalModel& model,
                                       const TemperatureRange& range, const Progress& progress = {});

Json to_json(const ThermalOptimizeResult& result);

}  // namespace scalcal::commands
