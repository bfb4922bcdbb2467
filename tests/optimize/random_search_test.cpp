// The hot loop's arithmetic (moments, LDL^T) against the eigen-decomposition of evaluate(), and
// the search's independence from the number of threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/synthesis/multistart.hpp"
#include "numeric/synthesis/random_search.hpp"
#include "numeric/synthesis/random_search_kernel.hpp"

namespace scalcal {
namespace {

TEST(RandomSearchKernel, AgreesWithEvaluate) {
  for (int n : {9, 13, 18, 31}) {
    const Program p = Program::random(n, static_cast<std::uint64_t>(n));
    std::vector<double> eta;
    for (const auto& e : p.positions) eta.insert(eta.end(), {e(0), e(1), e(2)});
    const Evaluation ev = evaluate(p);
    EXPECT_NEAR(score_positions(eta.data(), n, CriterionKind::D) / ev.value(CriterionKind::D), 1.0, 1e-10);
    EXPECT_NEAR(score_positions(eta.data(), n, CriterionKind::A) / ev.value(CriterionKind::A), 1.0, 1e-10);
    EXPECT_NEAR(score_positions(eta.data(), n, CriterionKind::E) / ev.value(CriterionKind::E), 1.0, 1e-10);
    EXPECT_NEAR(score_positions(eta.data(), n, CriterionKind::S) / ev.value(CriterionKind::S), 1.0, 1e-10);
  }
}

TEST(RandomSearchKernel, Classic18ByHand) {
  // The 18-position program: D = 17006112 and A = 78 (derived by hand in the paper's Fig. 1 case).
  const Program p = Program::classic18();
  std::vector<double> eta;
  for (const auto& e : p.positions) eta.insert(eta.end(), {e(0), e(1), e(2)});
  EXPECT_NEAR(score_positions(eta.data(), 18, CriterionKind::D), 17006112.0, 1e-6);
  EXPECT_NEAR(score_positions(eta.data(), 18, CriterionKind::A), 78.0, 1e-11);
}

TEST(RandomSearchKernel, RankDeficientIsInfinite) {
  std::vector<double> eta(27, 0.0);
  for (int i = 0; i < 9; ++i) eta[static_cast<std::size_t>(3 * i)] = (i % 2) ? 1.0 : -1.0;  // only +-x
  EXPECT_TRUE(std::isinf(score_positions(eta.data(), 9, CriterionKind::D)));
}

// The batched D of kBatch programs agrees with the one-program path; the early exit gives +infinity
// only when every program is worse than the threshold, and never hides a program that beats it.
TEST(RandomSearchKernel, BatchedDAndEarlyExit) {
  const int n = 18;
  Xoshiro256x4 rng(11);
  std::vector<double> xyz(static_cast<std::size_t>(3 * sample_buffer_size(n)));
  double* x = xyz.data();
  double* y = x + sample_buffer_size(n);
  double* z = y + sample_buffer_size(n);
  for (int trial = 0; trial < 200; ++trial) {
    double m[45][kBatch], single[kBatch];
    for (int l = 0; l < kBatch; ++l) {
      sample_sphere(rng, n, x, y, z);
      for (int i = 0; i < n; ++i) EXPECT_NEAR(x[i] * x[i] + y[i] * y[i] + z[i] * z[i], 1.0, 1e-14);
      double m45[45];
      accumulate_information(x, y, z, padded_size(n), n, m45);
      for (int e = 0; e < 45; ++e) m[e][l] = m45[e];
      single[l] = score_information(m45, n, CriterionKind::D);
    }
    double copy[45][kBatch], v[kBatch];
    std::copy(&m[0][0], &m[0][0] + 45 * kBatch, &copy[0][0]);
    d_criterion_batch(copy, n, 0.0, v);
    for (int l = 0; l < kBatch; ++l) EXPECT_NEAR(v[l] / single[l], 1.0, 1e-12);
    // Thresholds just below and above the best of the batch.
    const double best = *std::min_element(single, single + kBatch);
    for (double factor : {0.999, 1.001}) {
      std::copy(&m[0][0], &m[0][0] + 45 * kBatch, &copy[0][0]);
      d_criterion_batch(copy, n, det_needed_for(best * factor, n), v);
      const double got = *std::min_element(v, v + kBatch);
      if (factor > 1)
        EXPECT_NEAR(got / best, 1.0, 1e-12);  // the winner must survive
      else
        EXPECT_GE(got, best * factor);  // exited, or a true value above it
    }
  }
}

// The batched path (draw_disc_batch for kBatch programs, then batch_information across them) draws
// the same points and gives H^T H bit for bit as sample_sphere and accumulate_information one
// program at a time (the reference path, checked against evaluate() above), and leaves the
// generator in the same state; so does a short batch (the last of a chunk).
TEST(RandomSearchKernel, BatchedMomentsBitIdentical) {
  for (int n : {9, 12, 13, 18, 31, 40}) {
    Xoshiro256x4 one(static_cast<std::uint64_t>(100 + n)), batch(static_cast<std::uint64_t>(100 + n));
    const int stride = batch_stride(n);
    std::vector<double> disc(static_cast<std::size_t>(3 * kBatch * stride));
    std::vector<Programs> px(static_cast<std::size_t>(n)), py(px), pz(px);
    for (int trial = 0; trial < 20; ++trial) {
      draw_disc_batch(batch, n, kBatch, disc.data(), disc.data() + stride, disc.data() + 2 * stride, 3 * stride);
      double m[45][kBatch];
      batch_information(disc.data(), n, px.data(), py.data(), pz.data(), m);
      std::vector<double> xyz(static_cast<std::size_t>(3 * sample_buffer_size(n)));
      double* x = xyz.data();
      double* y = x + sample_buffer_size(n);
      double* z = y + sample_buffer_size(n);
      for (int l = 0; l < kBatch; ++l) {
        sample_sphere(one, n, x, y, z);
        double m45[45];
        accumulate_information(x, y, z, padded_size(n), n, m45);
        for (int i = 0; i < n; ++i) {
          ASSERT_EQ(px[i][l], x[i]) << "n " << n << " lane " << l << " position " << i;
          ASSERT_EQ(py[i][l], y[i]);
          ASSERT_EQ(pz[i][l], z[i]);
        }
        for (int e = 0; e < 45; ++e) ASSERT_EQ(m[e][l], m45[e]) << "n " << n << " lane " << l << " entry " << e;
      }
    }
    for (int lanes : {1, 3}) {
      draw_disc_batch(batch, n, lanes, disc.data(), disc.data() + stride, disc.data() + 2 * stride, 3 * stride);
      std::vector<double> xyz(static_cast<std::size_t>(3 * sample_buffer_size(n)));
      for (int l = 0; l < lanes; ++l) {
        sample_sphere(one, n, xyz.data(), xyz.data() + sample_buffer_size(n), xyz.data() + 2 * sample_buffer_size(n));
        for (int i = 0; i < n; ++i)  // the last coordinate: 1 - 2 s of the disc point
          ASSERT_EQ(xyz[static_cast<std::size_t>(2 * sample_buffer_size(n) + i)],
                    1.0 - 2.0 * disc[static_cast<std::size_t>((3 * l + 2) * stride + i)]);
      }
    }
    Xoshiro256x4::Words a, b;
    one.next(a);
    batch.next(b);
    for (int l = 0; l < 4; ++l) EXPECT_EQ(a[l], b[l]);
  }
}

#ifdef SCALCAL_HAVE_AVX512_DRAW
// draw_disc_batch compiled as random_search.cpp's AVX2 loop is (with FMA: s = u^2 + v^2 is one fused
// operation there, as in the AVX-512 loop, so the baseline's s may differ in its last bit).
__attribute__((target("avx2,fma,bmi,bmi2"))) void draw_disc_batch_avx2(Xoshiro256x4& rng, int n, int lanes, double* u,
                                                                       double* v, double* s, std::ptrdiff_t step) {
  draw_disc_batch(rng, n, lanes, u, v, s, step);
}

// The AVX-512 compaction keeps the same candidates in the same order as the scalar one, for whole and
// short batches, and leaves the generator in the same state.
TEST(RandomSearchKernel, Avx512DrawSameAsScalar) {
  __builtin_cpu_init();
  if (!__builtin_cpu_supports("avx512f") || !__builtin_cpu_supports("avx512vl") ||
      !__builtin_cpu_supports("avx512dq") || !__builtin_cpu_supports("avx512bw"))
    GTEST_SKIP() << "no AVX-512 here";
  for (int n : {1, 9, 18, 33}) {
    Xoshiro256x4 a(static_cast<std::uint64_t>(7 * n)), b(a);
    const int stride = batch_stride(n);
    std::vector<double> p(static_cast<std::size_t>(3 * kBatch * stride)), q(p);
    for (int trial = 0; trial < 50; ++trial) {
      const int lanes = 1 + trial % kBatch;
      draw_disc_batch_avx2(a, n, lanes, p.data(), p.data() + stride, p.data() + 2 * stride, 3 * stride);
      draw_disc_batch_avx512(b, n, lanes, q.data(), q.data() + stride, q.data() + 2 * stride, 3 * stride);
      for (int l = 0; l < lanes; ++l)
        for (int c = 0; c < 3; ++c)
          for (int i = 0; i < n; ++i) {
            const std::size_t at = static_cast<std::size_t>((3 * l + c) * stride + i);
            ASSERT_EQ(p[at], q[at]) << "n " << n << " lane " << l;
          }
    }
    Xoshiro256x4::Words wa, wb;
    a.next(wa);
    b.next(wb);
    for (int l = 0; l < 4; ++l) EXPECT_EQ(wa[l], wb[l]);
  }
}
#endif

TEST(RandomSearch, SameSeedSameResultWithAnyThreadCount) {
  const RandomSearchResult a = random_search(12, 50000, CriterionKind::D, 5, 1);
  const RandomSearchResult b = random_search(12, 50000, CriterionKind::D, 5, 2);
  const RandomSearchResult c = random_search(12, 50000, CriterionKind::D, 5, 3);
  EXPECT_EQ(a.best, b.best);
  EXPECT_EQ(a.best, c.best);
  ASSERT_EQ(a.program.size(), 12);
  EXPECT_EQ(a.program.positions[3], c.program.positions[3]);
  EXPECT_NEAR(evaluate(a.program).value(CriterionKind::D), a.best, 1e-6 * a.best);
  EXPECT_GE(a.best, 61509375.0 / 4.0);
}

}  // namespace
}  // namespace scalcal
