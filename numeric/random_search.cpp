// Random search on all cores. The R programs are cut into fixed chunks; chunk k has its own
// generator seeded by (seed, k), threads take chunks from an atomic counter, and the best is the
// lowest value, ties to the lowest (chunk, index): the result never depends on scheduling.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "numeric/random_search_kernel.hpp"
#include "numeric/synthesis.hpp"
#include "numeric/synthesis_local.hpp"

namespace scalcal {

namespace {

constexpr long long kChunk = 1 << 14;
constexpr std::uint64_t kRandomStream = 0x5241'4E44'4F4D'0001ull;  // keeps apart from multistart seeds

struct Best {
  double value = std::numeric_limits<double>::infinity();
  long long index = -1;  // global program index (chunk * kChunk + i)
  std::vector<double> eta;
};

}  // namespace

RandomSearchResult random_search(int positions, long long count, CriterionKind criterion, std::uint64_t seed,
                                 int threads) {
  if (positions < 9) throw std::invalid_argument("random_search: at least 9 positions are needed");
  if (count < 1) throw std::invalid_argument("random_search: count must be positive");
  const auto t0 = std::chrono::steady_clock::now();
  const long long chunks = (count + kChunk - 1) / kChunk;
  const int nthreads = static_cast<int>(std::min<long long>(thread_count(threads), chunks));
  std::vector<Best> best(static_cast<std::size_t>(nthreads));
  std::atomic<long long> next{0};
  auto worker = [&](int t) {
    Best& mine = best[static_cast<std::size_t>(t)];
    const std::size_t n3 = static_cast<std::size_t>(3 * positions);
    std::vector<double> eta(n3);  // the one buffer, reused by every program of this thread
    mine.eta.assign(n3, 0.0);
    for (long long c; (c = next.fetch_add(1)) < chunks;) {
      Xoshiro256 rng(start_seed(seed ^ kRandomStream, static_cast<std::uint64_t>(c)));
      const long long end = std::min(count, (c + 1) * kChunk);
      for (long long k = c * kChunk; k < end; ++k) {
        for (int i = 0; i < positions; ++i) sphere_point(rng, eta.data() + 3 * i);
        const double v = score_positions(eta.data(), positions, criterion);
        if (v < mine.value || (v == mine.value && k < mine.index)) {
          mine.value = v;
          mine.index = k;
          std::copy(eta.begin(), eta.end(), mine.eta.begin());
        }
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < nthreads; ++t) pool.emplace_back(worker, t);
  worker(0);
  for (auto& th : pool) th.join();

  const Best* winner = &best[0];
  for (const auto& b : best)
    if (b.index >= 0 && (winner->index < 0 || b.value < winner->value ||
                         (b.value == winner->value && b.index < winner->index)))
      winner = &b;
  RandomSearchResult out;
  out.count = count;
  for (int i = 0; i < positions; ++i)
    out.program.positions.emplace_back(winner->eta[3 * i], winner->eta[3 * i + 1], winner->eta[3 * i + 2]);
  out.best = winner->index >= 0 ? criterion_value(out.program, criterion) : winner->value;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace scalcal
