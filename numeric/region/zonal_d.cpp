// The D limit on one cap or band, as a one-dimensional problem (zonal_d.hpp).
#include "numeric/region/zonal_d.hpp"

#include "numeric/region/region.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>

#include <Eigen/Dense>
#include <boost/numeric/interval.hpp>

namespace scalcal {
namespace {

namespace bn = boost::numeric;
using I = bn::interval<double>;
using Quartic = std::array<double, 5>;
using QuarticI = std::array<I, 5>;

constexpr double kSphereLimit = 61509375.0 / 4.0;
constexpr int P = 9;

// The zone's heights z in [a, b] in the variable s = (z - mid) / half in [-1, 1]: the Hankel
// blocks of a small cap are then well conditioned.
struct Scale {
  double a, b, mid, half;
};

Scale scale_of(const Zone& zone) {
  const double deg = std::numbers::pi / 180.0;
  const double a = std::max(-1.0, std::cos(zone.max_tilt_deg * deg)),
               b = std::min(1.0, std::cos(zone.min_tilt_deg * deg));
  return {a, b, 0.5 * (a + b), 0.5 * (b - a)};
}

template <class T>
struct Blocks {
  T H[3][3];  // E[v v^T], v = (1, s, s^2)
  T B[2][2];  // E[r w w^T], w = (1, s), r = 1 - z^2
  T q;        // E[r^2]
};

template <class T>
Blocks<T> blocks(const Scale& sc, const std::vector<double>& z, const std::vector<double>& w) {
  Blocks<T> out;
  for (auto& row : out.H)
    for (auto& e : row) e = T(0.0);
  for (auto& row : out.B)
    for (auto& e : row) e = T(0.0);
  out.q = T(0.0);
  for (std::size_t i = 0; i < z.size(); ++i) {
    const T zi(z[i]), wi(w[i]);
    const T s = (zi - T(sc.mid)) / T(sc.half);
    const T r = (T(1.0) - zi) * (T(1.0) + zi);
    const T v[3] = {T(1.0), s, s * s};
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) out.H[j][k] += wi * v[j] * v[k];
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) out.B[j][k] += wi * r * v[j] * v[k];
    out.q += wi * r * r;
  }
  return out;
}

template <class T>
T det3(const T (&m)[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

template <class T>
T det2(const T (&m)[2][2]) {
  return m[0][0] * m[1][1] - m[0][1] * m[1][0];
}

// D = 1 / det M_h = 1024 / (det H_z det B_z^2 q^2), with det H_z = half^6 det H_s and
// det B_z = half^2 det B_s (M_h = T^-1 M_u T^-T with det T = 4, M_u = diag(H, B/2, B/2, q/2, q/2)).
template <class T>
T d_value(const Scale& sc, const Blocks<T>& bl) {
  T h10(1.0);
  for (int i = 0; i < 10; ++i) h10 *= T(sc.half);
  const T dB = det2(bl.B);
  return T(1024.0) / (h10 * det3(bl.H) * dB * dB * bl.q * bl.q);
}

template <class A, std::size_t N, std::size_t M>
std::array<A, N + M - 1> multiply(const std::array<A, N>& p, const std::array<A, M>& q) {
  std::array<A, N + M - 1> out;
  for (auto& c : out) c = A(0.0);
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < M; ++j) out[i + j] += p[i] * q[j];
  return out;
}

// The sensitivity d(s) = v^T H^-1 v + 2 r w^T B^-1 w + 2 r^2 / q as a quartic in s (inverses by
// adjugates, so intervals enclose them).
template <class T>
std::array<T, 5> sensitivity(const Scale& sc, const Blocks<T>& bl) {
  const auto& H = bl.H;
  const T dH = det3(H);
  T A[3][3];
  A[0][0] = (H[1][1] * H[2][2] - H[1][2] * H[2][1]) / dH;
  A[0][1] = -(H[0][1] * H[2][2] - H[0][2] * H[2][1]) / dH;
  A[0][2] = (H[0][1] * H[1][2] - H[0][2] * H[1][1]) / dH;
  A[1][1] = (H[0][0] * H[2][2] - H[0][2] * H[2][0]) / dH;
  A[1][2] = -(H[0][0] * H[1][2] - H[0][2] * H[1][0]) / dH;
  A[2][2] = (H[0][0] * H[1][1] - H[0][1] * H[1][0]) / dH;
  const T dB = det2(bl.B);
  const T B00 = bl.B[1][1] / dB, B01 = -bl.B[0][1] / dB, B11 = bl.B[0][0] / dB;
  const std::array<T, 5> hankel{A[0][0], T(2.0) * A[0][1], T(2.0) * A[0][2] + A[1][1], T(2.0) * A[1][2], A[2][2]};
  // r = 1 - (mid + half s)^2
  const std::array<T, 3> r{(T(1.0) - T(sc.mid)) * (T(1.0) + T(sc.mid)), T(-2.0) * T(sc.mid) * T(sc.half),
                           -(T(sc.half) * T(sc.half))};
  const std::array<T, 3> wBw{B00, T(2.0) * B01, B11};
  const auto rB = multiply(r, wBw);
  const auto r2 = multiply(r, r);
  std::array<T, 5> out;
  for (int k = 0; k < 5; ++k) out[k] = hankel[k] + T(2.0) * rB[k] + T(2.0) * r2[k] / bl.q;
  return out;
}

template <class T>
T horner(const std::array<T, 5>& c, const T& s) {
  T out = c[4];
  for (int k = 3; k >= 0; --k) out = out * s + c[k];
  return out;
}

template <class T>
T horner_derivative(const std::array<T, 5>& c, const T& s) {
  T out = T(4.0) * c[4];
  for (int k = 3; k >= 1; --k) out = out * s + T(static_cast<double>(k)) * c[k];
  return out;
}

// A proven upper bound on the interval quartic over [lo, hi]: branch and bound with the
// derivative's sign (monotone pieces give their end value) or a centred form.
double sup_quartic(const QuarticI& c, double lo, double hi) {
  struct Piece {
    double l, h, upper;
    bool operator<(const Piece& o) const { return upper < o.upper; }
  };
  const auto bound = [&](double l, double h) {
    const I S(l, h), D = horner_derivative(c, S);
    if (D.upper() <= 0) return horner(c, I(l)).upper();
    if (D.lower() >= 0) return horner(c, I(h)).upper();
    const double m = 0.5 * (l + h);
    return std::min(horner(c, S).upper(), (horner(c, I(m)) + D * (S - I(m))).upper());
  };
  std::priority_queue<Piece> queue;
  double best = -std::numeric_limits<double>::infinity();
  constexpr int kStart = 64;
  for (int i = 0; i < kStart; ++i) {
    const double l = lo + (hi - lo) * i / kStart, h = i + 1 == kStart ? hi : lo + (hi - lo) * (i + 1) / kStart;
    queue.push({l, h, bound(l, h)});
    best = std::max(best, horner(c, I(0.5 * (l + h))).lower());
  }
  for (int n = 0; n < 20000; ++n) {
    const Piece p = queue.top();
    if (p.upper - best <= 1e-15 * std::abs(p.upper) || p.h - p.l < 1e-14) break;
    queue.pop();
    const double m = 0.5 * (p.l + p.h);
    for (auto [l, h] : {std::pair{p.l, m}, std::pair{m, p.h}}) {
      queue.push({l, h, bound(l, h)});
      best = std::max(best, horner(c, I(0.5 * (l + h))).lower());
    }
  }
  return queue.top().upper;
}

// A measure on [a, b] with the moments (1, 0, 1/3, 0, 1/5) of the sphere's z, if the zone carries
// one (truncated Hausdorff moment problem): an atom at `fixed` and two more at the roots of the
// quadratic Q with E[(z - fixed) Q(z) z^j] = 0, j = 0, 1.
bool four_design_heights(double a, double b, std::vector<double>& z, std::vector<double>& w) {
  const double m[7] = {1.0, 0.0, 1.0 / 3.0, 0.0, 1.0 / 5.0, 0.0, 0.0};
  // E[(z - a)(b - z)(1, z)(1, z)^T] must be positive semidefinite.
  const double l00 = -m[2] + (a + b) * m[1] - a * b, l01 = -m[3] + (a + b) * m[2] - a * b * m[1],
               l11 = -m[4] + (a + b) * m[3] - a * b * m[2];
  if (l00 < 0 || l11 < 0 || l00 * l11 - l01 * l01 < 0) return false;
  for (double fixed : {b, a}) {
    // Q = z^2 + q1 z + q0: E[(z - f)(z^2 + q1 z + q0) z^j] = 0, j = 0, 1.
    const auto mom = [&](int k) { return m[k + 1] - fixed * m[k]; };  // E[(z - f) z^k]
    Eigen::Matrix2d A;
    A << mom(1), mom(0), mom(2), mom(1);
    const Eigen::Vector2d rhs(-mom(2), -mom(3));
    if (std::abs(A.determinant()) < 1e-14) continue;
    const Eigen::Vector2d q = A.fullPivLu().solve(rhs);
    const double disc = q(0) * q(0) - 4 * q(1);
    if (disc < 0) continue;
    const double t1 = 0.5 * (-q(0) - std::sqrt(disc)), t2 = 0.5 * (-q(0) + std::sqrt(disc));
    const double tol = 1e-12;
    if (t1 < a - tol || t2 > b + tol) continue;
    z = {fixed, std::clamp(t1, a, b), std::clamp(t2, a, b)};
    Eigen::Matrix3d V;
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) V(k, i) = std::pow(z[static_cast<std::size_t>(i)], k);
    const Eigen::Vector3d wv = V.fullPivLu().solve(Eigen::Vector3d(m[0], m[1], m[2]));
    if (wv.minCoeff() < 0) continue;
    w = {wv(0), wv(1), wv(2)};
    return true;
  }
  return false;
}

// The optimal weights and inner height on {a, t, b}: the multiplicative algorithm on a grid of
// heights finds the inner circle, Newton on d(a) = d(b) = 9, d'(t) = 0 settles it.
void three_circles(const Scale& sc, std::vector<double>& z, std::vector<double>& w) {
  constexpr int kGrid = 401;
  std::vector<double> grid(kGrid), wg(kGrid, 1.0 / kGrid);
  for (int i = 0; i < kGrid; ++i) grid[static_cast<std::size_t>(i)] = sc.mid + sc.half * (-1.0 + 2.0 * i / (kGrid - 1));
  for (int it = 0; it < 3000; ++it) {
    const auto c = sensitivity(sc, blocks<double>(sc, grid, wg));
    for (int i = 0; i < kGrid; ++i) wg[static_cast<std::size_t>(i)] *= horner(c, -1.0 + 2.0 * i / (kGrid - 1)) / P;
  }
  int inner = 1;
  for (int i = 1; i + 1 < kGrid; ++i)
    if (wg[static_cast<std::size_t>(i)] > wg[static_cast<std::size_t>(inner)]) inner = i;
  double wa = wg.front(), wb = wg.back(), s = -1.0 + 2.0 * inner / (kGrid - 1);
  const auto residual = [&](double pa, double pb, double ps) {
    const std::vector<double> zz{sc.a, sc.mid + sc.half * ps, sc.b}, ww{pa, 1 - pa - pb, pb};
    const auto c = sensitivity(sc, blocks<double>(sc, zz, ww));
    return Eigen::Vector3d(horner(c, -1.0) - P, horner(c, 1.0) - P, horner_derivative(c, ps));
  };
  // Weights near the grid's (its circle's mass is spread over neighbours: give it the rest).
  const double total = wa + wb;
  if (!(total > 0 && total < 1)) wa = wb = 1.0 / 3.0;
  for (int it = 0; it < 60; ++it) {
    const Eigen::Vector3d F = residual(wa, wb, s);
    if (F.norm() < 1e-14) break;
    Eigen::Matrix3d J;
    const double h = 1e-7;
    J.col(0) = (residual(wa + h, wb, s) - F) / h;
    J.col(1) = (residual(wa, wb + h, s) - F) / h;
    J.col(2) = (residual(wa, wb, s + h) - F) / h;
    Eigen::Vector3d step = J.fullPivLu().solve(-F);
    double damp = 1.0;  // stay inside: positive weights, an inner circle
    while (damp > 1e-6 && !(wa + damp * step(0) > 0 && wb + damp * step(1) > 0 &&
                            wa + wb + damp * (step(0) + step(1)) < 1 && std::abs(s + damp * step(2)) < 1))
      damp *= 0.5;
    wa += damp * step(0);
    wb += damp * step(1);
    s += damp * step(2);
  }
  z = {sc.a, sc.mid + sc.half * s, sc.b};
  w = {wa, 1 - wa - wb, wb};
}

}  // namespace

double zonal_d_value(const std::vector<double>& heights, const std::vector<double>& weights) {
  const Scale sc{-1.0, 1.0, 0.0, 1.0};
  return d_value(sc, blocks<double>(sc, heights, weights));
}

ZonalMeasure zonal_d_limit(const Zone& zone) {
  ZonalMeasure out;
  const Scale sc = scale_of(zone);
  if (four_design_heights(sc.a, sc.b, out.heights, out.weights)) {
    out.sphere_limit = true;
    out.value = kSphereLimit;
    out.lower_bound = kSphereLimit;  // proofs/d_limit.md: no measure on the sphere does better
    return out;
  }
  three_circles(sc, out.heights, out.weights);
  out.value = d_value(sc, blocks<double>(sc, out.heights, out.weights));
  // The certificate: D(nu) >= D(xi) (9 / m)^9 for every measure nu on the zone, m >= sup d_xi.
  const Blocks<I> bl = blocks<I>(sc, out.heights, out.weights);
  const QuarticI c = sensitivity(sc, bl);
  // The zone's s-range, widened outward: a slightly larger zone only makes the bound safer.
  const double eps = 8 * std::numeric_limits<double>::epsilon();
  const double lo = ((I(sc.a) - I(sc.mid)) / I(sc.half)).lower() - eps,
               hi = ((I(sc.b) - I(sc.mid)) / I(sc.half)).upper() + eps;
  const double m = sup_quartic(c, lo, hi);
  I bound = d_value(sc, bl);
  const I ratio = I(static_cast<double>(P)) / I(m);
  for (int i = 0; i < P; ++i) bound *= ratio;
  out.lower_bound = std::isfinite(bound.lower()) ? bound.lower() : 0.0;
  out.equivalence_gap = m / P - 1;
  return out;
}

void zonal_positions(const Zone& zone, const ZonalMeasure& measure, std::vector<Vec3>& positions,
                     std::vector<double>& weights) {
  const Vec3 a = zone.axis.normalized();
  const auto [e1, e2] = azimuth_frame(a);
  for (std::size_t i = 0; i < measure.heights.size(); ++i) {
    const double z = measure.heights[i], rho = std::sqrt(std::max(0.0, 1 - z * z));
    if (rho < 1e-12) {
      positions.push_back(z > 0 ? a : Vec3(-a));
      weights.push_back(measure.weights[i]);
      continue;
    }
    for (int k = 0; k < 5; ++k) {
      const double phi = 2 * std::numbers::pi * k / 5;
      positions.push_back((rho * (std::cos(phi) * e1 + std::sin(phi) * e2) + z * a).normalized());
      weights.push_back(measure.weights[i] / 5);
    }
  }
}

}  // namespace scalcal
