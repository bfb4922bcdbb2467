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

// The normalised criterion of n positions stored as xyz triples; +infinity when H^T H is not
// numerically positive definite. Only the lower triangle of the fixed 9x9 matrix is touched.
inline double score_positions(const double* eta, int n, CriterionKind criterion) {
  double m[9][9] = {};
  for (int i = 0; i < n; ++i) {
    const double x = eta[3 * i], y = eta[3 * i + 1], z = eta[3 * i + 2];
    const double h[9] = {x, y, z, x * x, y * y, z * z, x * y, y * z, z * x};
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b <= a; ++b) m[a][b] += h[a] * h[b];
  }
  const double N = n;
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (criterion == CriterionKind::E) {
    Mat9 M;
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b <= a; ++b) M(a, b) = M(b, a) = m[a][b];
    const double lmin = Eigen::SelfAdjointEigenSolver<Mat9>(M, Eigen::EigenvaluesOnly).eigenvalues()(0);
    return lmin > 0 ? N / lmin : inf;
  }
  // In-place Cholesky M = L L^T (lower triangle of m becomes L).
  double det = 1.0;
  for (int j = 0; j < 9; ++j) {
    double d = m[j][j];
    for (int k = 0; k < j; ++k) d -= m[j][k] * m[j][k];
    if (!(d > 1e-12 * N)) return inf;
    det *= d;
    const double ljj = std::sqrt(d);
    m[j][j] = ljj;
    const double inv = 1.0 / ljj;
    for (int i = j + 1; i < 9; ++i) {
      double s = m[i][j];
      for (int k = 0; k < j; ++k) s -= m[i][k] * m[j][k];
      m[i][j] = s * inv;
    }
  }
  if (criterion == CriterionKind::D) {
    double n9 = 1.0;
    for (int k = 0; k < 9; ++k) n9 *= N;
    return n9 / det;
  }
  // W = L^-1 (lower triangular); K = W^T W, so trace K = sum W_ij^2, K(r,r) = sum_k W_kr^2.
  double w[9][9] = {};
  for (int j = 0; j < 9; ++j) {
    w[j][j] = 1.0 / m[j][j];
    for (int i = j + 1; i < 9; ++i) {
      double s = 0.0;
      for (int k = j; k < i; ++k) s -= m[i][k] * w[k][j];
      w[i][j] = s / m[i][i];
    }
  }
  double result = 0.0;
  for (int r = 0; r < 9; ++r) {
    double krr = 0.0;
    for (int k = r; k < 9; ++k) krr += w[k][r] * w[k][r];
    result = criterion == CriterionKind::A ? result + krr : std::max(result, krr);
  }
  return N * result;
}

}  // namespace scalcal
