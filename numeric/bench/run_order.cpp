// Run orders (run_order.hpp): the fewest mountings, a nearest-neighbour path improved by 2-opt, and
// dynamic programming for the settings along an order.
#include "numeric/bench/run_order.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>

namespace scalcal {
namespace {

double step_cost(const Bench& bench, const BenchSetting& a, const BenchSetting& b) {
  return bench.travel(a, b) + (bench.remount(a, b) ? kRemountCostDeg : 0.0);
}

// b with its free axes where a left them.
BenchSetting inherit(const BenchSetting& a, BenchSetting b) {
  for (std::size_t k = 0; k < b.angles.size(); ++k)
    if (std::isnan(b.angles[k])) b.angles[k] = a.angles[k];
  return b;
}

// Axes still free at the start take the value of the first step that sets them (so they never
// move), or 0 (within the limits) when no step does.
void fill_leading(const Bench& bench, std::vector<RunStep>& steps) {
  const auto& axes = bench.axes();
  for (std::size_t k = 0; k < axes.size(); ++k) {
    double next = std::nan("");
    for (auto it = steps.rbegin(); it != steps.rend(); ++it) {
      double& a = it->setting.angles[k];
      if (std::isnan(a))
        a = next;
      else
        next = a;
    }
    for (auto& s : steps)
      if (std::isnan(s.setting.angles[k])) s.setting.angles[k] = std::clamp(0.0, axes[k].lo, axes[k].hi);
  }
}

bool better(const RunPlan& a, const RunPlan& b) {
  return a.remounts < b.remounts || (a.remounts == b.remounts && a.travel_deg < b.travel_deg - 1e-9);
}

bool remounts_possible(const Bench& bench) {
  return bench.mountings().size() > 1 && bench.remount(BenchSetting{0, {}}, BenchSetting{1, {}});
}

// The fewest mountings that reach every position (smallest subsets first, lower mountings first),
// and each position's choices on them.
std::vector<std::vector<BenchSetting>> on_fewest_mountings(const Bench& bench,
                                                           const std::vector<std::vector<BenchSetting>>& choices) {
  const int m = static_cast<int>(bench.mountings().size());
  if (!remounts_possible(bench) || m > 16) return choices;
  std::vector<unsigned> reach;
  for (const auto& c : choices) {
    unsigned mask = 0;
    for (const auto& s : c) mask |= 1u << s.mounting;
    reach.push_back(mask);
  }
  unsigned cover = (1u << m) - 1;
  for (int size = 1; size <= m; ++size) {
    bool found = false;
    for (unsigned mask = 1; mask < (1u << m) && !found; ++mask)
      if (std::popcount(mask) == size &&
          std::all_of(reach.begin(), reach.end(), [mask](unsigned r) { return (r & mask) != 0; })) {
        cover = mask;
        found = true;
      }
    if (found) break;
  }
  std::vector<std::vector<BenchSetting>> out = choices;
  for (auto& c : out) std::erase_if(c, [cover](const BenchSetting& s) { return !(cover >> s.mounting & 1u); });
  return out;
}

// The given order with each mounting's positions together (a position on the first of its
// mountings), mountings in the order they first appear.
std::vector<int> grouped_by_mounting(const std::vector<std::vector<BenchSetting>>& choices) {
  const int n = static_cast<int>(choices.size());
  std::vector<int> group(static_cast<std::size_t>(n)), rank;
  for (int i = 0; i < n; ++i) {
    int g = std::numeric_limits<int>::max();
    for (const auto& s : choices[static_cast<std::size_t>(i)]) g = std::min(g, s.mounting);
    group[static_cast<std::size_t>(i)] = g;
    if (std::find(rank.begin(), rank.end(), g) == rank.end()) rank.push_back(g);
  }
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  const auto position_of = [&](int g) { return std::find(rank.begin(), rank.end(), g) - rank.begin(); };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return position_of(group[static_cast<std::size_t>(a)]) < position_of(group[static_cast<std::size_t>(b)]);
  });
  return order;
}

using Distances = std::vector<std::vector<double>>;

// The least cost between any settings of two positions (a free axis costs nothing).
Distances distances(const Bench& bench, const std::vector<std::vector<BenchSetting>>& choices) {
  const std::size_t n = choices.size();
  Distances d(n, std::vector<double>(n, 0.0));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      double best = std::numeric_limits<double>::infinity();
      for (const auto& a : choices[i])
        for (const auto& b : choices[j]) best = std::min(best, step_cost(bench, a, b));
      d[i][j] = d[j][i] = best;
    }
  return d;
}

double path_length(const Distances& d, const std::vector<int>& p) {
  double s = 0;
  for (std::size_t k = 1; k < p.size(); ++k) s += d[static_cast<std::size_t>(p[k - 1])][static_cast<std::size_t>(p[k])];
  return s;
}

std::vector<int> nearest_neighbour(const Distances& d, int start) {
  const std::size_t n = d.size();
  std::vector<bool> seen(n, false);
  std::vector<int> path{start};
  seen[static_cast<std::size_t>(start)] = true;
  while (path.size() < n) {
    const auto& row = d[static_cast<std::size_t>(path.back())];
    int next = -1;
    for (std::size_t j = 0; j < n; ++j)
      if (!seen[j] && (next < 0 || row[j] < row[static_cast<std::size_t>(next)])) next = static_cast<int>(j);
    seen[static_cast<std::size_t>(next)] = true;
    path.push_back(next);
  }
  return path;
}

// 2-opt on an open path: reverse p[i..j] while that shortens it.
void two_opt(const Distances& d, std::vector<int>& p) {
  const std::size_t n = p.size();
  const auto D = [&](std::size_t a, std::size_t b) {
    return d[static_cast<std::size_t>(p[a])][static_cast<std::size_t>(p[b])];
  };
  for (int pass = 0; pass < 200; ++pass) {
    bool improved = false;
    for (std::size_t i = 0; i + 1 < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        double delta = 0;
        if (i > 0) delta += D(i - 1, j) - D(i - 1, i);
        if (j + 1 < n) delta += D(i, j + 1) - D(j, j + 1);
        if (delta < -1e-9) {
          std::reverse(p.begin() + static_cast<std::ptrdiff_t>(i), p.begin() + static_cast<std::ptrdiff_t>(j) + 1);
          improved = true;
        }
      }
    if (!improved) return;
  }
}

// Nearest neighbour from up to 64 starts; 2-opt on each path up to 100 positions, else on the
// shortest one only (2-opt costs O(N^2) a pass).
std::vector<int> shortest_path(const Distances& d) {
  const int n = static_cast<int>(d.size());
  const int starts = std::min(n, 64);
  std::vector<std::vector<int>> paths;
  for (int s = 0; s < starts; ++s)
    paths.push_back(nearest_neighbour(d, static_cast<int>(static_cast<long long>(s) * n / starts)));
  if (n > 100) {
    std::vector<int> p = *std::min_element(paths.begin(), paths.end(), [&](const auto& a, const auto& b) {
      return path_length(d, a) < path_length(d, b);
    });
    two_opt(d, p);
    return p;
  }
  std::vector<int> best;
  double best_length = std::numeric_limits<double>::infinity();
  for (auto& p : paths) {
    two_opt(d, p);
    if (const double l = path_length(d, p); l < best_length - 1e-9) {
      best_length = l;
      best = p;
    }
  }
  return best;
}

}  // namespace

void count_travel(const Bench& bench, RunPlan& plan) {
  plan.travel_deg = 0;
  plan.remounts = 0;
  for (std::size_t k = 1; k < plan.steps.size(); ++k) {
    plan.travel_deg += bench.travel(plan.steps[k - 1].setting, plan.steps[k].setting);
    plan.remounts += bench.remount(plan.steps[k - 1].setting, plan.steps[k].setting) ? 1 : 0;
  }
}

RunPlan run_in_order(const Bench& bench, const std::vector<std::vector<BenchSetting>>& choices,
                     const std::vector<int>& order) {
  const std::size_t n = order.size();
  std::vector<std::vector<BenchSetting>> state(n);
  std::vector<std::vector<double>> cost(n);
  std::vector<std::vector<int>> from(n);
  state[0] = choices[static_cast<std::size_t>(order[0])];
  cost[0].assign(state[0].size(), 0.0);
  from[0].assign(state[0].size(), -1);
  for (std::size_t k = 1; k < n; ++k) {
    for (const BenchSetting& c : choices[static_cast<std::size_t>(order[k])]) {
      int arg = 0;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t p = 0; p < state[k - 1].size(); ++p)
        if (const double v = cost[k - 1][p] + step_cost(bench, state[k - 1][p], c); v < best) {
          best = v;
          arg = static_cast<int>(p);
        }
      state[k].push_back(inherit(state[k - 1][static_cast<std::size_t>(arg)], c));
      cost[k].push_back(best);
      from[k].push_back(arg);
    }
  }
  RunPlan plan;
  plan.steps.resize(n);
  int at = static_cast<int>(std::min_element(cost[n - 1].begin(), cost[n - 1].end()) - cost[n - 1].begin());
  for (std::size_t k = n; k-- > 0;) {
    plan.steps[k] = RunStep{order[k], state[k][static_cast<std::size_t>(at)]};
    at = from[k][static_cast<std::size_t>(at)];
  }
  fill_leading(bench, plan.steps);
  count_travel(bench, plan);
  return plan;
}

RunPlan plan_run(const Bench& bench, const std::vector<std::vector<BenchSetting>>& choices, RunOrder order) {
  std::vector<int> given(choices.size());
  std::iota(given.begin(), given.end(), 0);
  RunPlan best = run_in_order(bench, choices, given);
  if (order == RunOrder::given || choices.size() < 2) return best;
  const auto fewest = on_fewest_mountings(bench, choices);
  std::vector<std::vector<int>> orders{grouped_by_mounting(fewest)};
  if (order == RunOrder::travel) orders.push_back(shortest_path(distances(bench, fewest)));
  for (const auto& o : orders)
    if (RunPlan p = run_in_order(bench, fewest, o); better(p, best)) best = std::move(p);
  // A path travels as far backwards: start on the first mounting (upright) when that costs nothing.
  if (order == RunOrder::travel && best.steps.front().setting.mounting > best.steps.back().setting.mounting) {
    std::vector<int> reversed;
    for (auto it = best.steps.rbegin(); it != best.steps.rend(); ++it) reversed.push_back(it->position);
    if (RunPlan p = run_in_order(bench, fewest, reversed); !better(best, p)) best = std::move(p);
  }
  return best;
}

}  // namespace scalcal
