// Restricted benches (issue 11's targets): optimize --region at N = 60 on a 30-degree cap for each
// criterion (target: under a minute on 2 cores), limits --region for all four criteria (target:
// under 10 s), and, as the baseline measured in the same run, a plain multistart on the hemisphere
// (uniform random starts in the cap, each polished by Ipopt inside it) against the exchange at
// N = 36 with the same number of starts. Counter `value`: the value reached, or for the hemisphere
// its ratio to the limit (one counter name throughout: the CSV reporter wants the same in every row).
#include <benchmark/benchmark.h>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/region/region_sampler.hpp"
#include "numeric/region/region_synthesis.hpp"
#include "numeric/synthesis/ipopt_local.hpp"
#include "numeric/synthesis/random_search_kernel.hpp"
#include "numeric/synthesis/seeds.hpp"
#include "numeric/synthesis/workers.hpp"

namespace {

using namespace scalcal;

void BM_RegionOptimize60(benchmark::State& state) {
  const CriterionKind c(static_cast<int>(state.range(0)));
  const Region cap = parse_region({"cap:30"});
  SynthesisResult r;
  for (auto _ : state) {
    SynthesisOptions o;
    o.positions = 60;
    o.criterion = c;
    o.threads = 2;
    r = synthesize_on_region(o, cap);
  }
  state.SetLabel(std::string(criterion_name(c)));
  state.counters["value"] = r.value;
}
BENCHMARK(BM_RegionOptimize60)->DenseRange(0, 3)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

void BM_RegionLimits(benchmark::State& state) {
  const char* specs[] = {"cap:90", "cap:30", "band:60:120", "faces:20"};
  const Region region = parse_region({specs[state.range(0)]});
  double d = 0;
  for (auto _ : state)
    for (auto c : kCriteria) {
      const RegionLimit l = region_limit(c, region);
      if (c == CriterionKind::D) d = l.value;
    }
  state.SetLabel(specs[state.range(0)]);
  state.counters["value"] = d;
}
BENCHMARK(BM_RegionLimits)->DenseRange(0, 3)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

constexpr double kHemisphereD = 9.39809328436720974e8;  // proofs/cap_d_limit.md
constexpr int kStarts = 8;

void BM_HemisphereD36Exchange(benchmark::State& state) {
  const Region cap = parse_region({"cap:90"});
  SynthesisResult r;
  for (auto _ : state) {
    SynthesisOptions o;
    o.positions = 36;
    o.starts = kStarts;
    o.threads = 2;
    r = synthesize_on_region(o, cap);
  }
  state.counters["value"] = r.value / kHemisphereD;
}
BENCHMARK(BM_HemisphereD36Exchange)->Iterations(3)->Unit(benchmark::kMillisecond)->UseRealTime();

// The baseline: what a user would write without the exchange.
void BM_HemisphereD36RandomStarts(benchmark::State& state) {
  const Region cap = parse_region({"cap:90"});
  const PositionSampler sample = region_sampler(cap);
  double best = 0;
  for (auto _ : state) {
    const std::vector<LocalResult> results = run_in_workers(kStarts, 2, 36, [&](int k) {
      Xoshiro256x4 rng(start_seed(1, static_cast<std::uint64_t>(k)));
      double x[48], y[48], z[48];
      sample(rng, 36, x, y, z);
      Program p;
      for (int i = 0; i < 36; ++i) p.positions.emplace_back(x[i], y[i], z[i]);
      const PositionBounds bounds = position_bounds(cap, p.positions);
      return optimize_with_ipopt<DCriterion>(p, {}, &bounds);
    });
    best = INFINITY;
    for (const auto& r : results) best = std::min(best, r.value);
  }
  state.counters["value"] = best / kHemisphereD;
}
BENCHMARK(BM_HemisphereD36RandomStarts)->Iterations(3)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
