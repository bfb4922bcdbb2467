// Region limits computed side by side in worker processes (region_limits.hpp).
#include "numeric/region/region_limits.hpp"

#include <algorithm>
#include <cstddef>
#include <numeric>

#include "numeric/region/cap_limits.hpp"
#include "numeric/synthesis/workers.hpp"

namespace scalcal {
namespace {

// A RegionLimit crosses the workers' pipe as a fixed-size record of doubles (run_values_in_workers).
// Supports larger than kMaxSupport come back empty and are computed again here.
constexpr int kMaxSupport = 2000;
constexpr int kHeader = 8 + 81;  // ok, value, has bound, bound, gap, candidates, refinements, boxes; K
constexpr int kRecordSize = kHeader + 1 + 4 * kMaxSupport;  // then n, 3n coordinates, n weights

std::vector<double> pack(const RegionLimit& l) {
  std::vector<double> out(static_cast<std::size_t>(kRecordSize), 0.0);
  const std::size_t n = l.support.size();
  if (n > static_cast<std::size_t>(kMaxSupport)) return out;  // out[0] = 0: not carried
  out[0] = 1;
  out[1] = l.value;
  out[2] = l.lower_bound ? 1.0 : 0.0;
  out[3] = l.lower_bound.value_or(0.0);
  out[4] = l.equivalence_gap;
  out[5] = l.candidates;
  out[6] = l.refinements;
  out[7] = static_cast<double>(l.boxes);
  for (int i = 0; i < 81; ++i) out[static_cast<std::size_t>(8 + i)] = l.K(i / 9, i % 9);
  out[kHeader] = static_cast<double>(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) out[kHeader + 1 + 3 * i + static_cast<std::size_t>(c)] = l.support[i](c);
    out[kHeader + 1 + 3 * n + i] = l.weights[i];
  }
  return out;
}

bool unpack(const std::vector<double>& in, RegionLimit& l) {
  if (in[0] != 1) return false;
  l.value = in[1];
  if (in[2] != 0) l.lower_bound = in[3];
  l.equivalence_gap = in[4];
  l.candidates = static_cast<int>(in[5]);
  l.refinements = static_cast<int>(in[6]);
  l.boxes = static_cast<long>(in[7]);
  for (int i = 0; i < 81; ++i) l.K(i / 9, i % 9) = in[static_cast<std::size_t>(8 + i)];
  const auto n = static_cast<std::size_t>(in[kHeader]);
  for (std::size_t i = 0; i < n; ++i) {
    l.support.emplace_back(in[kHeader + 1 + 3 * i], in[kHeader + 2 + 3 * i], in[kHeader + 3 + 3 * i]);
    l.weights.push_back(in[kHeader + 1 + 3 * n + i]);
  }
  return true;
}

// A rough cost, for handing out the longest tasks first (so that one does not start last and leave
// the other workers idle): the first candidate grid's size, and nothing for D on one cap or band,
// which is one-dimensional (zonal_d.hpp). Only the order of hand-out depends on it, not a result.
std::size_t rough_cost(const RegionLimitTask& t, const RegionLimitOptions& options) {
  if (t.criterion == CriterionKind::D && is_single_zone(t.region)) return 0;
  return t.region.measure_grid(options.grid_step_deg).size();
}

}  // namespace

std::vector<RegionLimit> region_limits(const std::vector<RegionLimitTask>& tasks, const RegionLimitOptions& options,
                                       int workers, const std::function<void(int, int)>& progress) {
  std::vector<RegionLimit> out(tasks.size());
  // A theorem's closed form takes no time: here, not in a worker (and its theorem's name stays with it).
  std::vector<std::size_t> solve;
  for (std::size_t k = 0; k < tasks.size(); ++k)
    if (options.closed_forms && cap_closed_form(tasks[k].criterion, tasks[k].region))
      out[k] = region_limit(tasks[k].criterion, tasks[k].region, options);
    else
      solve.push_back(k);
  const int count = static_cast<int>(tasks.size()), done = count - static_cast<int>(solve.size());
  const auto report = [&](int n, int) {
    if (progress) progress(done + n, count);
  };
  if (workers <= 1 || solve.size() <= 1) {
    int n = 0;
    for (std::size_t k : solve) {
      out[k] = region_limit(tasks[k].criterion, tasks[k].region, options);
      report(++n, count);
    }
    return out;
  }
  std::vector<std::size_t> cost(tasks.size());
  for (std::size_t k : solve) cost[k] = rough_cost(tasks[k], options);
  std::vector<std::size_t> order = solve;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });
  const std::vector<std::vector<double>> records = run_values_in_workers(
      static_cast<int>(order.size()), workers, kRecordSize,
      [&](int j) {
        const RegionLimitTask& t = tasks[order[static_cast<std::size_t>(j)]];
        return pack(region_limit(t.criterion, t.region, options));
      },
      report);
  for (std::size_t j = 0; j < order.size(); ++j) {
    const std::size_t k = order[j];
    if (!unpack(records[j], out[k])) out[k] = region_limit(tasks[k].criterion, tasks[k].region, options);
  }
  return out;
}

}  // namespace scalcal
