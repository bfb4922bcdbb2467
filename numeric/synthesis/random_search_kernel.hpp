// The hot loop of random search: draw a program into fixed buffers, accumulate H^T H in place,
// factor it and score it, with no allocation per program. Generator: four xoshiro256** streams
// (Blackman & Vigna 2018) in SIMD lanes, seeded by splitmix64; sphere points by Marsaglia's (1972)
// method, one 64-bit draw per candidate, rejection by branch-free compaction. Two paths give the
// same bits: one program at a time (sample_sphere, accumulate_information: the reference), and
// kBatch programs at once with one program per lane (draw_disc_batch, batch_information).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <Eigen/Eigenvalues>
#if defined(__GNUC__) && defined(__x86_64__)
#include <immintrin.h>
#endif

#include "numeric/criteria/registry.hpp"
#include "numeric/model/paper9.hpp"
#include "numeric/synthesis/seeds.hpp"

namespace scalcal {

// The kernels below are forced inline, so that each machine-specific clone of the search loop
// (random_search.cpp: target_clones) compiles them for its own instruction set.
#if defined(__GNUC__)
#define SCALCAL_KERNEL inline __attribute__((always_inline))
#else
#define SCALCAL_KERNEL inline
#endif

// Positions are processed kLanes at a time; buffers hold a multiple of kLanes (padded with zero
// vectors, which add nothing to H^T H: every entry is a monomial of degree 2 to 4).
inline constexpr int kLanes = 4;
// Programs whose LDL^T factorisations run side by side (d_criterion_batch).
inline constexpr int kBatch = 8;
constexpr int padded_size(int n) { return (n + kLanes - 1) / kLanes * kLanes; }
// Room each coordinate buffer of sample_sphere needs for n points.
constexpr int sample_buffer_size(int n) { return padded_size(n) + kLanes; }
// Room for one coordinate of one program in a batch's buffer of disc points (draw_disc_batch): n +
// kLanes for the compaction's overrun, rounded up to whole 8 x 8 blocks for the transposition.
constexpr int batch_stride(int n) { return (n + kLanes + 7) / 8 * 8; }

// Four xoshiro256** streams side by side (lane l of each state word; GCC/Clang vector extension),
// seeded by one splitmix64 chain from the seed: stream l's four words follow stream l-1's.
class Xoshiro256x4 {
 public:
  typedef std::uint64_t Words __attribute__((vector_size(4 * sizeof(std::uint64_t))));
  explicit Xoshiro256x4(std::uint64_t seed) {
    for (int l = 0; l < 4; ++l)
      for (auto& w : s_) w[l] = seed = splitmix64(seed);
  }
  // (Results go through a reference: vector types by value would change the ABI without AVX.)
  void next(Words& result) {
    const Words m = s_[1] * 5;
    result = ((m << 7) | (m >> 57)) * 9;
    const Words t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = (s_[3] << 45) | (s_[3] >> 19);
  }

 private:
  Words s_[4];
};

typedef double Reals4 __attribute__((vector_size(4 * sizeof(double))));

// Marsaglia (1972): (u, v) uniform in the unit disc, s = u^2 + v^2, gives
// (2u sqrt(1-s), 2v sqrt(1-s), 1 - 2s) uniform on the sphere. Each 64-bit draw r of each stream is
// one candidate: u from its high and v from its low 32 bits, as 2^-31 fixed point in [-1, 1) (put
// into the mantissa of a double in [2, 4), minus 3). Accepted where 0 < s < 1.
SCALCAL_KERNEL void disc_candidates(const Xoshiro256x4::Words& r, Reals4& u, Reals4& v, Reals4& s) {
  const Xoshiro256x4::Words two = Xoshiro256x4::Words{} + 0x4000000000000000ull;
  const Xoshiro256x4::Words ub = ((r >> 32) << 20) | two, vb = ((r & 0xFFFFFFFFull) << 20) | two;
  std::memcpy(&u, &ub, sizeof u);
  std::memcpy(&v, &vb, sizeof v);
  u -= 3.0;
  v -= 3.0;
  s = u * u + v * v;
}

// n accepted candidates for each of `lanes` programs in a row, program l's u, v, s at u, v, s + l
// step (each with room for n + kLanes). Candidates go in order (draw, stream); the accepted ones are
// kept by branch-free compaction. A program ends at the draw that completes its n points (the rest
// of that draw is dropped) and the next begins at the next draw; the switch is branch-free too, so
// the loop's exit is mispredicted once per batch instead of once per program.
SCALCAL_KERNEL void draw_disc_batch(Xoshiro256x4& rng, int n, int lanes, double* u, double* v, double* s,
                                    std::ptrdiff_t step) {
  typedef std::int64_t Mask __attribute__((vector_size(4 * sizeof(std::int64_t))));
  Xoshiro256x4 local = rng;  // in registers: the stores below could alias the caller's generator
  int program = 0, k = 0;
  std::ptrdiff_t at = 0;  // program * step
  while (program < lanes) {
    Xoshiro256x4::Words r;
    local.next(r);
    Reals4 U, V, S;
    disc_candidates(r, U, V, S);
    const Mask accept = (S < 1.0) & (S > 0.0);  // -1 where accepted
    for (int l = 0; l < 4; ++l) {
      u[at + k] = U[l];
      v[at + k] = V[l];
      s[at + k] = S[l];
      k -= static_cast<int>(accept[l]);
    }
    const int done = k >= n;
    program += done;
    k = done ? 0 : k;
    at = program * step;
  }
  rng = local;
}

// One program: n accepted candidates into u, v, s.
SCALCAL_KERNEL void draw_disc_points(Xoshiro256x4& rng, int n, double* u, double* v, double* s) {
  draw_disc_batch(rng, n, 1, u, v, s, 0);
}

#if defined(__GNUC__) && defined(__x86_64__)
#define SCALCAL_HAVE_AVX512_DRAW 1
#define SCALCAL_AVX512_TARGET "avx512f,avx512dq,avx512vl,avx512bw,avx2,fma,bmi,bmi2,popcnt"
// draw_disc_batch with AVX-512's compress in place of the scalar compaction: the same candidates
// kept in the same order, a third faster (random_search.cpp's AVX-512 loop; only where the CPU has
// it). The empty asm keeps the compiler from folding the generator's * 9 into the << 20 as one slow
// 64-bit vector multiply.
__attribute__((target(SCALCAL_AVX512_TARGET))) inline void draw_disc_batch_avx512(Xoshiro256x4& rng, int n, int lanes,
                                                                                  double* u, double* v, double* s,
                                                                                  std::ptrdiff_t step) {
  Xoshiro256x4 local = rng;
  int program = 0, k = 0;
  std::ptrdiff_t at = 0;
  while (program < lanes) {
    Xoshiro256x4::Words r;
    local.next(r);
    asm("" : "+v"(r));
    Reals4 U, V, S;
    disc_candidates(r, U, V, S);
    const __m256d s4 = reinterpret_cast<__m256d>(S);
    const __mmask8 accept = _mm256_cmp_pd_mask(s4, _mm256_set1_pd(1.0), _CMP_LT_OQ) &
                            _mm256_cmp_pd_mask(s4, _mm256_setzero_pd(), _CMP_GT_OQ);
    _mm256_storeu_pd(u + at + k, _mm256_maskz_compress_pd(accept, reinterpret_cast<__m256d>(U)));
    _mm256_storeu_pd(v + at + k, _mm256_maskz_compress_pd(accept, reinterpret_cast<__m256d>(V)));
    _mm256_storeu_pd(s + at + k, _mm256_maskz_compress_pd(accept, s4));
    k += __builtin_popcount(accept);
    const int done = k >= n;
    program += done;
    k = done ? 0 : k;
    at = program * step;
  }
  rng = local;
}
#endif

// Marsaglia's map of accepted disc points (u, v, s) to the sphere, in place: (x, y, z) replaces
// (u, v, s). R is double or a vector of doubles, W the unsigned 64-bit integers of the same shape;
// every lane goes through the same operations, so a program's points do not depend on the width.
// 2 sqrt(1 - s): 1/sqrt(a) from the bit-level estimate (relative error < 3.5e-2) and four Newton
// steps (< 1e-20 before rounding; std::sqrt does not vectorise: errno), then sqrt(a) = a / sqrt(a):
// points are unit vectors to a few ulp. For s in (0, 1) only: other values may be slow or NaN.
template <class R, class W>
SCALCAL_KERNEL void disc_to_sphere(R& x, R& y, R& s) {
  const R a = 1.0 - s;
  W bits;
  std::memcpy(&bits, &a, sizeof bits);
  bits = 0x5FE6EB50C7B537A9ull - (bits >> 1);
  R q;
  std::memcpy(&q, &bits, sizeof q);
  for (int it = 0; it < 4; ++it) q = q * (1.5 - 0.5 * a * q * q);
  const R r = 2.0 * a * q;
  x *= r;
  y *= r;
  s = 1.0 - 2.0 * s;
}

// n points uniform on the sphere into x, y, z (each with room for sample_buffer_size(n)), zero
// vectors after the n-th up to padded_size(n).
SCALCAL_KERNEL void sample_sphere(Xoshiro256x4& rng, int n, double* x, double* y, double* z) {
  typedef Reals4 Reals;
  draw_disc_points(rng, n, x, y, z);
  for (int k = n; k < padded_size(n); ++k) z[k] = 0.0;  // s = 0: a harmless a = 1 in the padding
  for (int k = 0; k < padded_size(n); k += 4) {
    Reals X, Y, S;
    std::memcpy(&X, x + k, sizeof X);
    std::memcpy(&Y, y + k, sizeof Y);
    std::memcpy(&S, z + k, sizeof S);
    disc_to_sphere<Reals, Xoshiro256x4::Words>(X, Y, S);
    std::memcpy(x + k, &X, sizeof X);
    std::memcpy(y + k, &Y, sizeof Y);
    std::memcpy(z + k, &S, sizeof S);
  }
  for (int k = n; k < padded_size(n); ++k) x[k] = y[k] = z[k] = 0.0;
}

// H^T H has only 31 distinct entries: the sums of the monomials of degree 2, 3 and 4 in
// (x, y, z), listed by degree, then by decreasing power of x, then of y (xx, xy, xz, yy, ...).
// Accumulating those does 31 multiply-adds per position instead of the 45 + 6 of h_a h_b.
struct MomentTable {
  int entry[9][9];  // H^T H(a, b) = moment[entry[a][b]]
};

constexpr MomentTable make_moment_table() {
  MomentTable t{};
  int exps[31][3] = {};
  int count = 0;
  for (int degree = 2; degree <= 4; ++degree)
    for (int a = degree; a >= 0; --a)
      for (int b = degree - a; b >= 0; --b) {
        const int e[3] = {a, b, degree - a - b};
        exps[count][0] = e[0];
        exps[count][1] = e[1];
        exps[count][2] = e[2];
        ++count;
      }
  const int h[9][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 0, 0}, {0, 2, 0},
                       {0, 0, 2}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}};
  for (int a = 0; a < 9; ++a)
    for (int b = 0; b < 9; ++b)
      for (int k = 0; k < 31; ++k)
        if (exps[k][0] == h[a][0] + h[b][0] && exps[k][1] == h[a][1] + h[b][1] && exps[k][2] == h[a][2] + h[b][2])
          t.entry[a][b] = k;
  return t;
}

inline constexpr MomentTable kMoments = make_moment_table();

// The 45 entries of the lower triangle of H^T H, packed (a, b), b <= a, at a(a+1)/2 + b.
constexpr int packed(int a, int b) { return a * (a + 1) / 2 + b; }

// The 24 accumulated moment sums (accumulate_information says which) plus the point (X, Y, Z): V is
// a vector of kLanes positions of one program or of one position of kBatch programs. One body for
// both paths, so their sums round alike (the same expressions, fused alike).
template <class V>
SCALCAL_KERNEL void add_moments(V* acc, const V& X, const V& Y, const V& Z) {
  const V xx = X * X, xy = X * Y, xz = X * Z, yy = Y * Y, yz = Y * Z, zz = Z * Z;
  acc[0] += xx, acc[1] += xy, acc[2] += xz, acc[3] += yy, acc[4] += yz;
  acc[5] += X * xx, acc[6] += X * xy, acc[7] += X * xz, acc[8] += X * yy, acc[9] += X * yz;
  acc[10] += X * zz, acc[11] += Y * yy, acc[12] += Y * yz, acc[13] += Y * zz, acc[14] += Z * zz;
  acc[15] += xx * xx, acc[16] += xx * xy, acc[17] += xx * xz, acc[18] += xx * yy, acc[19] += xx * yz;
  acc[20] += xy * yy, acc[21] += xy * yz, acc[22] += yy * yy, acc[23] += yy * yz;
}

// The 31 moments in kMoments' order (degree, then decreasing powers of x, then of y) from the 24
// sums a of `count` unit vectors (V: double, or one lane per program).
template <class V>
SCALCAL_KERNEL void derive_moments(const V* a, double count, V* m) {
  for (int k = 0; k < 5; ++k) m[k] = a[k];                     // xx xy xz yy yz
  m[5] = count - a[0] - a[3];                                  // zz
  for (int k = 6; k <= 15; ++k) m[k] = a[k - 1];               // the ten cubic moments
  m[16] = a[15], m[17] = a[16], m[18] = a[17], m[19] = a[18];  // xxxx xxxy xxxz xxyy
  m[20] = a[19], m[22] = a[20], m[23] = a[21], m[26] = a[22];  // xxyz xyyy xyyz yyyy
  m[27] = a[23];                                               // yyyz
  m[21] = m[0] - m[16] - m[19];                                // xxzz
  m[24] = m[1] - m[17] - m[22];                                // xyzz
  m[25] = m[2] - m[18] - m[23];                                // xzzz
  m[28] = m[3] - m[19] - m[26];                                // yyzz
  m[29] = m[4] - m[20] - m[27];                                // yzzz
  m[30] = m[5] - m[21] - m[28];                                // zzzz
}

// Moments of `count` unit vectors in structure-of-arrays form (n, a multiple of kLanes, includes
// the zero padding), kLanes partial sums per moment held in one vector (GCC/Clang vector
// extension: AVX where compiled for it, else pairs of SSE2 registers); the partial sums are added
// in a fixed order. Only 24 of the 31 moments are accumulated (fewer registers spilled): on the
// sphere x^2 + y^2 + z^2 = 1, so sum z^2 = count - sum x^2 - sum y^2 and every quartic moment with
// a factor z^2 is m - m x^2 - m y^2 for a quadratic monomial m.
SCALCAL_KERNEL void accumulate_information(const double* x, const double* y, const double* z, int n, int count,
                                           double* m45) {
  typedef double Lanes __attribute__((vector_size(kLanes * sizeof(double))));
  Lanes acc[24] = {};
  for (int i = 0; i < n; i += kLanes) {
    Lanes X, Y, Z;
    std::memcpy(&X, x + i, sizeof X);
    std::memcpy(&Y, y + i, sizeof Y);
    std::memcpy(&Z, z + i, sizeof Z);
    add_moments(acc, X, Y, Z);
  }
  double a[24];
  for (int k = 0; k < 24; ++k) {
    double s = 0.0;
    for (int l = 0; l < kLanes; ++l) s += acc[k][l];
    a[k] = s;
  }
  double m[31];
  derive_moments(a, static_cast<double>(count), m);
  for (int r = 0; r < 9; ++r)
    for (int c = 0; c <= r; ++c) m45[packed(r, c)] = m[kMoments.entry[r][c]];
}

// kBatch programs side by side, one per lane (GCC/Clang vector extension: one AVX-512 register, two
// AVX2 ones, four SSE2 ones).
typedef double Programs __attribute__((vector_size(kBatch * sizeof(double))));
typedef std::uint64_t ProgramWords __attribute__((vector_size(kBatch * sizeof(std::uint64_t))));

// The 8 x 8 block r (row l: 8 values of program l) transposed in place (row i: value i of every
// program), in three rounds of two-vector shuffles.
SCALCAL_KERNEL void transpose_block(Programs* r) {
  static_assert(kBatch == 8, "transpose_block handles 8 x 8 blocks");
  Programs t[8], w[8];
  for (int k = 0; k < 4; ++k) {
    t[2 * k] = __builtin_shufflevector(r[2 * k], r[2 * k + 1], 0, 8, 2, 10, 4, 12, 6, 14);
    t[2 * k + 1] = __builtin_shufflevector(r[2 * k], r[2 * k + 1], 1, 9, 3, 11, 5, 13, 7, 15);
  }
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j) {
      w[4 * k + j] = __builtin_shufflevector(t[4 * k + j], t[4 * k + j + 2], 0, 1, 8, 9, 4, 5, 12, 13);
      w[4 * k + j + 2] = __builtin_shufflevector(t[4 * k + j], t[4 * k + j + 2], 2, 3, 10, 11, 6, 7, 14, 15);
    }
  for (int j = 0; j < 4; ++j) {
    r[j] = __builtin_shufflevector(w[j], w[j + 4], 0, 1, 2, 3, 8, 9, 10, 11);
    r[j + 4] = __builtin_shufflevector(w[j], w[j + 4], 4, 5, 6, 7, 12, 13, 14, 15);
  }
}

// H^T H of kBatch programs into m[45][kBatch] (packed lower triangles), from their accepted disc
// points (draw_disc_batch: program l's u, v, s at disc + (3 l + c) batch_stride(n), c = 0, 1, 2).
// The points are transposed to one program per lane and mapped to the sphere into x, y, z (room for
// n each); then the moments are accumulated as accumulate_information does for one program: the
// same kLanes partial sums (position i into partial i mod kLanes, in increasing i), added in the
// same order, the same derived moments. So every program's H^T H is bit for bit the one of
// sample_sphere and accumulate_information, with 8 programs per instruction instead of 4 positions
// and no sums across lanes; the zero padding is skipped (it adds exact zeros: no sum is ever -0).
SCALCAL_KERNEL void batch_information(const double* __restrict disc, int n, Programs* __restrict x,
                                      Programs* __restrict y, Programs* __restrict z, double (*m)[kBatch]) {
  const int stride = batch_stride(n);
  int i0 = 0;
  for (; i0 + 4 < n; i0 += 8) {  // whole blocks while more than 4 positions are left
    Programs block[3][8];
    for (int c = 0; c < 3; ++c) {
      for (int l = 0; l < kBatch; ++l)
        std::memcpy(&block[c][l], disc + static_cast<std::ptrdiff_t>((3 * l + c) * stride + i0), sizeof(Programs));
      transpose_block(block[c]);
    }
    for (int j = 0; j < 8 && i0 + j < n; ++j) {  // past n: the compaction's leftovers, never mapped
      disc_to_sphere<Programs, ProgramWords>(block[0][j], block[1][j], block[2][j]);
      x[i0 + j] = block[0][j];
      y[i0 + j] = block[1][j];
      z[i0 + j] = block[2][j];
    }
  }
  for (int i = i0; i < n; ++i) {  // the last 1 to 4 one at a time: cheaper than a whole block
    Programs c3[3];
    for (int c = 0; c < 3; ++c)
      for (int l = 0; l < kBatch; ++l) c3[c][l] = disc[(3 * l + c) * stride + i];
    disc_to_sphere<Programs, ProgramWords>(c3[0], c3[1], c3[2]);
    x[i] = c3[0];
    y[i] = c3[1];
    z[i] = c3[2];
  }
  Programs partial[kLanes][24];
  for (int p = 0; p < kLanes; ++p) {
    Programs acc[24] = {};
    for (int i = p; i < n; i += kLanes) {
      add_moments(acc, x[i], y[i], z[i]);
    }
    for (int k = 0; k < 24; ++k) partial[p][k] = acc[k];
  }
  Programs a[24];
  for (int k = 0; k < 24; ++k) {
    Programs s = Programs{} + 0.0;
    for (int p = 0; p < kLanes; ++p) s += partial[p][k];
    a[k] = s;
  }
  Programs mo[31];
  derive_moments(a, static_cast<double>(n), mo);
  for (int r = 0; r < 9; ++r)
    for (int c = 0; c <= r; ++c) std::memcpy(m[packed(r, c)], &mo[kMoments.entry[r][c]], sizeof(Programs));
}

// D = N^9 / det(H^T H) of B programs at once (m[entry][program], packed lower triangles), by
// right-looking LDL^T across the programs: the same operations, in the same order, as one program
// alone, so a program's value does not depend on its neighbours. +infinity for a pivot <= 1e-12 N.
// Early exit: after pivot j, det M <= d_0 ... d_j S_{j+1,j+1} ... S_88 (Hadamard's inequality on
// the Schur complement S; in floating point too, since every update only subtracts d_j l^2 >= 0 from
// a diagonal entry and products of smaller positive factors are smaller). When that bound is below
// `det_needed` for every program, none of them can be a new best, and all get +infinity. The
// factorisation is a chain of 9 dependent divisions: kBatch = 8 programs side by side fill an
// AVX-512 vector, or two AVX2 ones whose chains overlap (4 at a time left it latency-bound).
template <int B>
SCALCAL_KERNEL void d_criterion_batch(double (*m)[B], int n, double det_needed, double* out) {
  const double N = n;
  double n9 = 1.0;
  for (int k = 0; k < 9; ++k) n9 *= N;
  double det[B], ok[B];
  for (int l = 0; l < B; ++l) det[l] = 1.0, ok[l] = 1.0;
  const double tiny = 1e-12 * N;
#pragma GCC unroll 9
  for (int j = 0; j < 9; ++j) {
    double inv[B];
    for (int l = 0; l < B; ++l) {
      const double d = m[packed(j, j)][l];
      ok[l] = d > tiny ? ok[l] : 0.0;
      det[l] *= d;
      inv[l] = 1.0 / d;
    }
#pragma GCC unroll 9
    for (int i = j + 1; i < 9; ++i) {
      double lij[B];
      for (int l = 0; l < B; ++l) lij[l] = m[packed(i, j)][l] * inv[l];
#pragma GCC unroll 9
      for (int k = j + 1; k <= i; ++k)
        for (int l = 0; l < B; ++l) m[packed(i, k)][l] -= lij[l] * m[packed(k, j)][l];
    }
    if (j == 2 || j == 5) {
      bool any = false;
      for (int l = 0; l < B; ++l) {
        double bound = det[l];
        for (int k = j + 1; k < 9; ++k) bound *= m[packed(k, k)][l];
        any |= ok[l] != 0.0 && !(bound < det_needed);
      }
      if (!any) {
        for (int l = 0; l < B; ++l) out[l] = std::numeric_limits<double>::infinity();
        return;
      }
    }
  }
  for (int l = 0; l < B; ++l) out[l] = ok[l] != 0.0 ? n9 / det[l] : std::numeric_limits<double>::infinity();
}

// The determinant a program must exceed to have D below `best` (with a relative margin of 1e-12,
// so that rounding can never exit early on a program that would win).
SCALCAL_KERNEL double det_needed_for(double best, int n) {
  if (!(best < std::numeric_limits<double>::infinity())) return 0.0;
  double n9 = 1.0;
  for (int k = 0; k < 9; ++k) n9 *= n;
  return n9 / best * (1.0 - 1e-12);
}

// K = M^-1 read off the LDL^T factorisation of M (no square roots on the critical path), computed
// only as far as the criterion asks: det K from the pivots, K(r,r) = sum_k W_kr^2 / d_k with
// W = L^-1, lambda_max(K) from an eigen-decomposition of M.
class LdltInverseInformation {
 public:
  LdltInverseInformation(const double* m45, int n) {
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b <= a; ++b) m_[a][b] = M_(a, b) = M_(b, a) = m45[packed(a, b)];
    det_M_ = 1.0;
    for (int j = 0; j < 9; ++j) {
      double dj = m_[j][j];
      for (int k = 0; k < j; ++k) dj -= m_[j][k] * m_[j][k] * d_[k];
      if (!(dj > 1e-12 * n)) return;
      d_[j] = dj;
      det_M_ *= dj;
      const double inv = 1.0 / dj;
      for (int i = j + 1; i < 9; ++i) {
        double s = m_[i][j];
        for (int k = 0; k < j; ++k) s -= m_[i][k] * m_[j][k] * d_[k];
        m_[i][j] = s * inv;
      }
    }
    positive_definite_ = true;
  }

  bool positive_definite() const { return positive_definite_; }
  int parameters() const { return 9; }
  double det() const { return 1.0 / det_M_; }
  double diagonal(int r) const {
    if (!have_diagonal_) fill_diagonal();
    return diagonal_[r];
  }
  // K(r,c) = sum_k W_kr W_kc / d_k.
  double entry(int r, int c) const {
    if (!have_diagonal_) fill_diagonal();
    double k = 0.0;
    for (int j = std::max(r, c); j < 9; ++j) k += w_[j][r] * w_[j][c] / d_[j];
    return k;
  }
  double trace() const {
    double t = 0.0;
    for (int r = 0; r < 9; ++r) t += diagonal(r);
    return t;
  }
  double max_eigenvalue() const {
    return 1.0 / Eigen::SelfAdjointEigenSolver<Mat9>(M_, Eigen::EigenvaluesOnly).eigenvalues()(0);
  }

 private:
  void fill_diagonal() const {
    auto& w = w_;
    for (int j = 0; j < 9; ++j) {
      w[j][j] = 1.0;
      for (int i = j + 1; i < 9; ++i) {
        double s = 0.0;
        for (int k = j; k < i; ++k) s -= m_[i][k] * w[k][j];
        w[i][j] = s;
      }
    }
    for (int r = 0; r < 9; ++r) {
      double krr = 0.0;
      for (int k = r; k < 9; ++k) krr += w[k][r] * w[k][r] / d_[k];
      diagonal_[r] = krr;
    }
    have_diagonal_ = true;
  }

  double m_[9][9] = {};  // lower triangle: M, then L strictly below the diagonal
  double d_[9] = {};
  double det_M_ = 0.0;
  Mat9 M_;
  bool positive_definite_ = false;
  mutable bool have_diagonal_ = false;
  mutable double diagonal_[9] = {};
  mutable double w_[9][9] = {};  // L^-1
};

// The normalised criterion C from the packed lower triangle of H^T H; +infinity when H^T H is not
// numerically positive definite.
template <Criterion C>
double score_information(const double* m45, int n) {
  const LdltInverseInformation k(m45, n);
  if (!k.positive_definite()) return std::numeric_limits<double>::infinity();
  return C::template value<Paper9Model>(k, static_cast<double>(n));
}

inline double score_information(const double* m45, int n, CriterionKind criterion) {
  return visit_criterion(criterion, [&](auto C) { return score_information<decltype(C)>(m45, n); });
}

// The normalised criterion of n unit vectors stored as xyz triples (the kernel's reference entry).
inline double score_positions(const double* eta, int n, CriterionKind criterion) {
  const int np = padded_size(n);
  std::vector<double> x(static_cast<std::size_t>(np), 0.0), y(x), z(x);
  for (int i = 0; i < n; ++i) x[i] = eta[3 * i], y[i] = eta[3 * i + 1], z[i] = eta[3 * i + 2];
  double m45[45];
  accumulate_information(x.data(), y.data(), z.data(), np, n, m45);
  return score_information(m45, n, criterion);
}

}  // namespace scalcal
