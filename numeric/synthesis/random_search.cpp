// Random search on all cores. The R programs are cut into fixed chunks; chunk k has its own
// generator seeded by (seed, k), threads take chunks from an atomic counter, and the best is the
// lowest value, ties to the lowest (chunk, index): the result never depends on scheduling.
// Programs are drawn kBatch at a time (on AVX-512 machines, H^T H of the batch too, one program per
// SIMD lane: batch_information); for D their LDL^T factorisations run side by side (one SIMD lane
// each) and stop early when none of them can beat the thread's best so far (a program that is
// strictly worse than some program can never be the overall best, so this is scheduling-proof).
#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "numeric/synthesis/random_search.hpp"
#include "numeric/synthesis/random_search_kernel.hpp"

#include "numeric/criteria/evaluation.hpp"
#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/io/interrupt.hpp"
#include "numeric/synthesis/seeds.hpp"

namespace scalcal {

namespace {

constexpr long long kChunk = 1 << 14;
constexpr std::uint64_t kRandomStream = 0x5241'4E44'4F4D'0001ull;  // keeps apart from multistart seeds

struct Best {
  double value = std::numeric_limits<double>::infinity();
  long long index = -1;     // global program index (chunk * kChunk + i)
  std::vector<double> eta;  // xyz triples
};

struct Buffers {
  explicit Buffers(int n)
      : stride(sample_buffer_size(n)),
        xyz(static_cast<std::size_t>(3 * kBatch * stride)),
        batch(static_cast<std::size_t>(3 * n + 3 * batch_stride(n))),
        px(batch.data()),
        py(px + n),
        pz(py + n),
        disc(reinterpret_cast<double*>(pz + n)) {}
  double* x(int lane) { return xyz.data() + static_cast<std::size_t>(3 * lane * stride); }
  double* y(int lane) { return x(lane) + stride; }
  double* z(int lane) { return x(lane) + 2 * stride; }
  int stride;
  std::vector<double> xyz;  // one program per lane, for a bench's sampler or another model
  // The paper's model on the sphere, one block: the unit vectors of a batch (one program per lane),
  // then its accepted disc points (draw_disc_batch: 3 kBatch rows of batch_stride(n)), all 64-byte
  // aligned, since batch_information reads and writes them 8 at a time; one block, so that their
  // relative place, and with it the speed, does not depend on malloc (separate vectors ran at 8.4 to
  // 12 M programs/s depending on where they fell).
  std::vector<Programs> batch;
  Programs *px, *py, *pz;
  double* disc;
};

void consider(Best& mine, double v, long long k, const double* x, const double* y, const double* z, int n) {
  if (v < mine.value || (v == mine.value && k < mine.index)) {
    mine.value = v;
    mine.index = k;
    for (int i = 0; i < n; ++i) {
      mine.eta[static_cast<std::size_t>(3 * i)] = x[i];
      mine.eta[static_cast<std::size_t>(3 * i + 1)] = y[i];
      mine.eta[static_cast<std::size_t>(3 * i + 2)] = z[i];
    }
  }
}

void consider(Best& mine, double v, long long k, Buffers& buf, int lane, int n) {
  consider(mine, v, k, buf.x(lane), buf.y(lane), buf.z(lane), n);
}

// The same for program `lane` of a batch_information batch: its unit vectors are read back from
// the lanes of px, py, pz (only for a new best: take() tests first).
void consider_batched(Best& mine, double v, long long k, Buffers& buf, int lane, int n) {
  std::vector<double> x(static_cast<std::size_t>(n)), y(x), z(x);
  for (int i = 0; i < n; ++i) x[i] = buf.px[i][lane], y[i] = buf.py[i][lane], z[i] = buf.pz[i][lane];
  consider(mine, v, k, x.data(), y.data(), z.data(), n);
}

SCALCAL_KERNEL void take(Best& mine, double v, long long k, Buffers& buf, int lane, int n, bool on_sphere) {
  if (!(v < mine.value || (v == mine.value && k < mine.index))) return;  // the usual case, kept inline
  if (on_sphere)
    consider_batched(mine, v, k, buf, lane, n);
  else
    consider(mine, v, k, buf, lane, n);
}

// The normalised criterion C of model M for n positions in x, y, z: H^T H by rank-one updates and
// K from its eigen-decomposition (+infinity when H^T H is not numerically positive definite).
template <class M, Criterion C>
double score_model_positions(const double* x, const double* y, const double* z, int n) {
  constexpr int P = M::kParameters;
  InformationT<M, double> info = InformationT<M, double>::Zero();
  for (int i = 0; i < n; ++i) {
    const RowT<M, double> h = M::row(Vec3(x[i], y[i], z[i]));
    info.template selfadjointView<Eigen::Lower>().rankUpdate(h);
  }
  const Eigen::SelfAdjointEigenSolver<InformationT<M, double>> es(info.template selfadjointView<Eigen::Lower>());
  const RowT<M, double> lambda = es.eigenvalues();  // ascending
  if (!(lambda(0) > 64 * P * std::numeric_limits<double>::epsilon() * lambda(P - 1)))
    return std::numeric_limits<double>::infinity();
  const RowT<M, double> inv = lambda.cwiseInverse();
  const InformationT<M, double> K = es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose();
  const InverseInformation<double, P> k{K, inv};
  return C::template value<M>(k, static_cast<double>(n));
}

using ModelScore = double (*)(const double*, const double*, const double*, int);

// Programs begin..end-1 of one chunk. `score` is the criterion's score_information<C>; `batched` its
// kDeterminantOnly path; a non-null `model_score` (a model other than the paper's) replaces both.
// Inlined into one entry per instruction set below. With a `draw` (draw_disc_batch_avx512), the
// paper's model on the sphere draws a batch of programs at once and computes their H^T H across
// them (batch_information); without, one program at a time as for a bench or another model: with
// 16 AVX2 or SSE2 registers, batch_information's 24 moments of 8 programs spill, and it is no
// faster (AVX2) or a third slower (SSE2) than one program at a time.
using DrawDiscBatch = void (*)(Xoshiro256x4&, int, int, double*, double*, double*, std::ptrdiff_t);
template <DrawDiscBatch draw>
SCALCAL_KERNEL void search_chunk_body(Xoshiro256x4& rng, long long begin, long long end, int n,
                                      double (*score)(const double*, int), bool batched, ModelScore model_score,
                                      const PositionSampler& sampler, Buffers& buf, Best& mine) {
  alignas(64) double m[45][kBatch];
  double m45[45];
  // The unit vectors of lane l are in x, y, z (a bench's sampler, another model) or in the lanes of
  // px, py, pz (the paper's model on the sphere, batch_information).
  const bool on_sphere = draw != nullptr && !sampler && !model_score;
  for (long long k0 = begin; k0 < end; k0 += kBatch) {
    if (interrupt_requested()) return;  // random_search throws once its threads have stopped
    const int lanes = static_cast<int>(std::min<long long>(kBatch, end - k0));
    if (on_sphere) {
      if constexpr (draw != nullptr) {
        // All lanes drawn first (their stores have left the core when batch_information reads them
        // back across programs), then H^T H of all at once.
        const int stride = batch_stride(n);
        draw(rng, n, lanes, buf.disc, buf.disc + stride, buf.disc + 2 * stride, 3 * stride);
        batch_information(buf.disc, n, buf.px, buf.py, buf.pz, m);
      }
    } else {
      for (int l = 0; l < lanes; ++l) {
        if (sampler)
          sampler(rng, n, buf.x(l), buf.y(l), buf.z(l));
        else
          sample_sphere(rng, n, buf.x(l), buf.y(l), buf.z(l));
        if (model_score) continue;
        accumulate_information(buf.x(l), buf.y(l), buf.z(l), padded_size(n), n, m45);
        for (int e = 0; e < 45; ++e) m[e][l] = m45[e];
      }
    }
    if (model_score) {
      for (int l = 0; l < lanes; ++l) consider(mine, model_score(buf.x(l), buf.y(l), buf.z(l), n), k0 + l, buf, l, n);
    } else if (batched) {
      for (int l = lanes; l < kBatch; ++l)
        for (int e = 0; e < 45; ++e) m[e][l] = m[e][0];  // padding lanes repeat lane 0, then are ignored
      double v[kBatch];
      d_criterion_batch(m, n, det_needed_for(mine.value, n), v);
      for (int l = 0; l < lanes; ++l) take(mine, v[l], k0 + l, buf, l, n, on_sphere);
    } else {
      for (int l = 0; l < lanes; ++l) {
        for (int e = 0; e < 45; ++e) m45[e] = m[e][l];
        take(mine, score(m45, n), k0 + l, buf, l, n, on_sphere);
      }
    }
  }
}

using SearchChunk = void (*)(Xoshiro256x4&, long long, long long, int, double (*)(const double*, int), bool, ModelScore,
                             const PositionSampler&, Buffers&, Best&);

#define SCALCAL_SEARCH_CHUNK_ARGS                                                                              \
  Xoshiro256x4 &rng, long long begin, long long end, int n, double (*score)(const double*, int), bool batched, \
      ModelScore model_score, const PositionSampler &sampler, Buffers &buf, Best &mine
void search_chunk_baseline(SCALCAL_SEARCH_CHUNK_ARGS) {
  search_chunk_body<nullptr>(rng, begin, end, n, score, batched, model_score, sampler, buf, mine);
}

// The search loop compiled once per instruction set and chosen at run time (x86-64: AVX-512, AVX2 + FMA
// or the baseline). Not target_clones: its ifunc resolver picked the baseline on the development
// machine (an AMD EPYC with AVX-512), where __builtin_cpu_supports, asked after start-up, knows better.
// All draw the same programs; values may differ in the last bits (FMA), so only programs within
// rounding of each other could swap places.
#if defined(__GNUC__) && defined(__x86_64__)
__attribute__((target(SCALCAL_AVX512_TARGET))) void search_chunk_avx512(SCALCAL_SEARCH_CHUNK_ARGS) {
  search_chunk_body<&draw_disc_batch_avx512>(rng, begin, end, n, score, batched, model_score, sampler, buf, mine);
}
__attribute__((target("avx2,fma,bmi,bmi2"))) void search_chunk_avx2(SCALCAL_SEARCH_CHUNK_ARGS) {
  search_chunk_body<nullptr>(rng, begin, end, n, score, batched, model_score, sampler, buf, mine);
}
SearchChunk pick_search_chunk() {
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl") &&
      __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2"))
    return &search_chunk_avx512;
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2"))
    return &search_chunk_avx2;
  return &search_chunk_baseline;
}
#else
SearchChunk pick_search_chunk() { return &search_chunk_baseline; }
#endif
#undef SCALCAL_SEARCH_CHUNK_ARGS

}  // namespace

RandomSearchResult random_search(int positions, long long count, CriterionKind criterion, std::uint64_t seed,
                                 int threads, const PositionSampler& sampler, ModelKind model) {
  const int parameters = model_parameters(model);
  if (positions < parameters)
    throw std::invalid_argument("random_search: at least " + std::to_string(parameters) + " positions are needed");
  if (count < 1) throw std::invalid_argument("random_search: count must be positive");
  const auto t0 = std::chrono::steady_clock::now();
  const long long chunks = (count + kChunk - 1) / kChunk;
  const auto score = visit_criterion(criterion, [](auto C) { return &score_information<decltype(C)>; });
  const bool batched = visit_criterion(criterion, [](auto C) { return kDeterminantOnly<decltype(C)>; });
  const ModelScore model_score =
      model_supports(model, ModelCapability::criteria_native) ? nullptr : visit_model(model, [criterion](auto M) {
        return visit_criterion(criterion,
                               [](auto C) -> ModelScore { return &score_model_positions<decltype(M), decltype(C)>; });
      });
  static const SearchChunk search_chunk = pick_search_chunk();
  const int nthreads = static_cast<int>(std::min<long long>(thread_count(threads), chunks));
  std::vector<Best> best(static_cast<std::size_t>(nthreads));
  std::atomic<long long> next{0};
  auto worker = [&](int t) {
    Best& mine = best[static_cast<std::size_t>(t)];
    Buffers buf(positions);  // reused by every program of this thread
    mine.eta.assign(static_cast<std::size_t>(3 * positions), 0.0);
    for (long long c; (c = next.fetch_add(1)) < chunks;) {
      Xoshiro256x4 rng(start_seed(seed ^ kRandomStream, static_cast<std::uint64_t>(c)));
      search_chunk(rng, c * kChunk, std::min(count, (c + 1) * kChunk), positions, score, batched, model_score, sampler,
                   buf, mine);
    }
  };
  std::vector<std::thread> pool;
  // A thread the system refuses (ulimit -u) leaves the chunks to fewer threads: the same results.
  for (int t = 1; t < nthreads; ++t) try {
      pool.emplace_back(worker, t);
    } catch (const std::system_error&) {
      break;
    }
  worker(0);
  for (auto& th : pool) th.join();
  check_interrupt();

  const Best* winner = &best[0];
  for (const auto& b : best)  // the threads not started kept index -1
    if (b.index >= 0 &&
        (winner->index < 0 || b.value < winner->value || (b.value == winner->value && b.index < winner->index)))
      winner = &b;
  RandomSearchResult out;
  out.count = count;
  for (int i = 0; i < positions; ++i)
    out.program.positions.emplace_back(winner->eta[3 * i], winner->eta[3 * i + 1], winner->eta[3 * i + 2]);
  out.best = winner->index < 0                                         ? winner->value
             : model_supports(model, ModelCapability::criteria_native) ? criterion_value(out.program, criterion)
                                                                       : evaluate(model, out.program).value(criterion);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace scalcal
