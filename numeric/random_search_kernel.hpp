// The hot loop of random search: draw a program into a fixed buffer, accumulate H^T H in place,
// Cholesky-factor it and score it, with no allocation per program. Generator: xoshiro256**
// (Blackman & Vigna 2018) seeded by splitmix64; sphere points by Marsaglia's (1972) method.
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/Eigenvalues>

#include "numeric/criterion_kind.hpp"
#include "numeric/synthesis_seeds.hpp"
#include "numeric/types.hpp"

namespace scalcal {

class Xoshiro256 {
 public:
  explicit Xoshiro256(std::uint64_t seed) {
    for (auto& w : s_) w = seed = splitmix64(seed);
  }
  std::uint64_t operator()() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }
  // Uniform in [-1, 1) from the top 53 bits.
  double symmetric() { return static_cast<double>((*this)() >> 11) * 0x1.0p-52 - 1.0; }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4];
};

// Marsaglia: (u, v) uniform in the unit disc, s = u^2 + v^2, gives
// (2u sqrt(1-s), 2v sqrt(1-s), 1 - 2s) uniform on the sphere.
inline void sphere_point(Xoshiro256& rng, double* out) {
  double u, v, s;
  do {
    u = rng.symmetric();
    v = rng.symmetric();
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double r = 2.0 * std::sqrt(1.0 - s);
  out[0] = u * r;
  out[1] = v * r;
  out[2] = 1.0 - 2.0 * s;
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

// The normalised criterion of n positions stored as xyz triples; +infinity when H^T H is not
// numerically positive definite. Only the lower triangle of the fixed 9x9 matrix is touched.
inline double score_positions(const double* eta, int n, CriterionKind criterion) {
  double acc[31] = {};
  for (int i = 0; i < n; ++i) {
    const double x = eta[3 * i], y = eta[3 * i + 1], z = eta[3 * i + 2];
    const double xx = x * x, xy = x * y, xz = x * z, yy = y * y, yz = y * z, zz = z * z;
    const double mono[31] = {xx, xy, xz, yy, yz, zz,
                             x * xx, x * xy, x * xz, x * yy, x * yz, x * zz, y * yy, y * yz, y * zz, z * zz,
                             xx * xx, xx * xy, xx * xz, xx * yy, xx * yz, xx * zz, xy * yy, xy * yz, xy * zz,
                             xz * zz, yy * yy, yy * yz, yy * zz, yz * zz, zz * zz};
    for (int k = 0; k < 31; ++k) acc[k] += mono[k];
  }
  double m[9][9];
  for (int a = 0; a < 9; ++a)
    for (int b = 0; b <= a; ++b) m[a][b] = acc[kMoments.entry[a][b]];
  const double N = n;
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (criterion == CriterionKind::E) {
    Mat9 M;
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b <= a; ++b) M(a, b) = M(b, a) = m[a][b];
    const double lmin = Eigen::SelfAdjointEigenSolver<Mat9>(M, Eigen::EigenvaluesOnly).eigenvalues()(0);
    return lmin > 0 ? N / lmin : inf;
  }
  // In-place LDL^T (no square roots on the critical path): the strict lower triangle of m becomes
  // L, d the pivots; det M = prod d.
  double d[9];
  double det = 1.0;
  for (int j = 0; j < 9; ++j) {
    double dj = m[j][j];
    for (int k = 0; k < j; ++k) dj -= m[j][k] * m[j][k] * d[k];
    if (!(dj > 1e-12 * N)) return inf;
    d[j] = dj;
    det *= dj;
    const double inv = 1.0 / dj;
    for (int i = j + 1; i < 9; ++i) {
      double s = m[i][j];
      for (int k = 0; k < j; ++k) s -= m[i][k] * m[j][k] * d[k];
      m[i][j] = s * inv;
    }
  }
  if (criterion == CriterionKind::D) {
    double n9 = 1.0;
    for (int k = 0; k < 9; ++k) n9 *= N;
    return n9 / det;
  }
  // W = L^-1 (unit lower triangular); K = W^T D^-1 W, so K(r,r) = sum_k W_kr^2 / d_k.
  double w[9][9] = {};
  for (int j = 0; j < 9; ++j) {
    w[j][j] = 1.0;
    for (int i = j + 1; i < 9; ++i) {
      double s = 0.0;
      for (int k = j; k < i; ++k) s -= m[i][k] * w[k][j];
      w[i][j] = s;
    }
  }
  double result = 0.0;
  for (int r = 0; r < 9; ++r) {
    double krr = 0.0;
    for (int k = r; k < 9; ++k) krr += w[k][r] * w[k][r] / d[k];
    result = criterion == CriterionKind::A ? result + krr : std::max(result, krr);
  }
  return N * result;
}

}  // namespace scalcal
