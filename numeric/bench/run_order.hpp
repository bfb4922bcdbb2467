// The order to run a program's positions on a bench and the setting of each: fewest remounts first
// (a remount is work by hand and disturbs the meter), then least travel of the axes. Remounts: the
// fewest mountings that reach every position (every subset tried, smallest first), each visited
// once. Travel: a travelling-salesman path over the positions (nearest neighbour from every start,
// then 2-opt), with the distance of two positions the least travel between any of their settings;
// the settings along the chosen order are then picked by dynamic programming. Every candidate order
// (and the given one) is scored exactly and the best kept, so the plan never travels more than the
// given order does with its best settings.
#pragma once
#include <vector>

#include "numeric/bench/registry.hpp"

namespace scalcal {

enum class RunOrder {
  travel,    // fewest remounts, then least travel
  remounts,  // fewest remounts, the given order within each mounting
  given,     // the program's order
};

struct RunStep {
  int position = 0;  // index into the program (0-based)
  BenchSetting setting;
};

struct RunPlan {
  std::vector<RunStep> steps;  // in run order
  double travel_deg = 0;       // the axes' travel from the first step to the last
  int remounts = 0;
};

// A remount costs as much as this much travel when orders are compared: more than any travel.
inline constexpr double kRemountCostDeg = 1e7;

// choices[i]: every setting that measures position i (none empty). Free axes (NaN) are resolved:
// such an axis stays where the step before left it.
RunPlan plan_run(const Bench& bench, const std::vector<std::vector<BenchSetting>>& choices, RunOrder order);

// The best settings along a fixed order (dynamic programming over the choices).
RunPlan run_in_order(const Bench& bench, const std::vector<std::vector<BenchSetting>>& choices,
                     const std::vector<int>& order);

// Travel and remounts of the steps as they stand (angles already resolved).
void count_travel(const Bench& bench, RunPlan& plan);

}  // namespace scalcal
