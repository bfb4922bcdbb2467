// Random search at N = 18 (programs per second on one core); one D start at N = 18 by Ipopt and
// by Riemannian Newton; and the whole D multistart at N = 18 on one core (workers, Ipopt's
// confirmation of the best, the distinct-optimum count), per start.
#include <benchmark/benchmark.h>

#include "numeric/synthesis/ipopt_local.hpp"
#include "numeric/synthesis/multistart.hpp"
#include "numeric/synthesis/newton_local.hpp"
#include "numeric/synthesis/random_search.hpp"

namespace {

void BM_RandomSearchD18(benchmark::State& state) {
  const long long count = 200000;
  for (auto _ : state) benchmark::DoNotOptimize(scalcal::random_search(18, count, scalcal::CriterionKind::D, 1, 1));
  state.counters["programs_per_s"] =
      benchmark::Counter(double(count) * double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RandomSearchD18)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_NewtonStartD18(benchmark::State& state) {
  std::uint64_t seed = 1;
  for (auto _ : state)
    benchmark::DoNotOptimize(scalcal::optimize_with_newton<scalcal::DCriterion>(scalcal::Program::random(18, seed++)));
}
BENCHMARK(BM_NewtonStartD18)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_MultistartD18(benchmark::State& state) {
  const int starts = 64;
  std::uint64_t seed = 1;
  for (auto _ : state) {
    scalcal::SynthesisOptions o;
    o.positions = 18;
    o.starts = starts;
    o.threads = 1;
    o.seed = seed++;
    benchmark::DoNotOptimize(scalcal::synthesize(o));
  }
  state.SetItemsProcessed(state.iterations() * starts);  // items: starts (a CSV column every row has)
}
BENCHMARK(BM_MultistartD18)->Unit(benchmark::kMillisecond)->UseRealTime();

// Last: it initialises MUMPS in this process, after which synthesize()'s forked workers could not
// use it (see synthesis.cpp).
void BM_IpoptStartD18(benchmark::State& state) {
  std::uint64_t seed = 1;
  for (auto _ : state)
    benchmark::DoNotOptimize(scalcal::optimize_with_ipopt<scalcal::DCriterion>(scalcal::Program::random(18, seed++)));
}
BENCHMARK(BM_IpoptStartD18)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
