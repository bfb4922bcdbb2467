// Random search at N = 18 (programs per second on one core) and one Ipopt D start at N = 18.
#include <benchmark/benchmark.h>

#include "numeric/synthesis.hpp"
#include "numeric/synthesis_local.hpp"

namespace {

void BM_RandomSearchD18(benchmark::State& state) {
  const long long count = 200000;
  for (auto _ : state) benchmark::DoNotOptimize(scalcal::random_search(18, count, scalcal::CriterionKind::D, 1, 1));
  state.counters["programs_per_s"] = benchmark::Counter(double(count) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RandomSearchD18)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_IpoptStartD18(benchmark::State& state) {
  std::uint64_t seed = 1;
  for (auto _ : state)
    benchmark::DoNotOptimize(scalcal::optimize_locally(scalcal::Program::random(18, seed++), scalcal::CriterionKind::D));
}
BENCHMARK(BM_IpoptStartD18)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
