// The proven closed forms of a cap's limits (cap_limits.hpp), evaluated in long double.
#include "numeric/region/cap_limits.hpp"

#include <cmath>
#include <numbers>

namespace scalcal {
namespace {

// A half-angle this close to a threshold (in the cosine) is left to the certified solver.
constexpr long double kThresholdMargin = 1e-12L;

long double pow_int(long double x, int n) {
  long double out = 1;
  for (int i = 0; i < n; ++i) out *= x;
  return out;
}

bool is_coordinate_axis(const Vec3& a) {
  int zeros = 0, units = 0;
  for (int k = 0; k < 3; ++k) {
    if (a(k) == 0.0) ++zeros;
    if (std::abs(a(k)) == 1.0) ++units;
  }
  return zeros == 2 && units == 1;
}

// Theorem 8: for c > c* the pole (1/9), the rim (8 alpha/9) and the circle z = t (8 (1 - alpha)/9),
// t the only root of P(c, .) in (c, 1) (P(c, c) > 0 > P(c, 1): bisection), alpha from E2 = 0, which
// is linear in alpha; for c <= c* the sphere's limit on the pole, z = c* and z = (sqrt 6 - 1)/5.
CapClosedForm cap_d(long double c) {
  CapClosedForm f;
  f.theorem = "proofs/cap_d_limit.md";
  if (c <= kCapDSphereCosine) {
    const long double s6 = std::sqrt(6.0L);
    f.sphere_limit = true;
    f.value = 61509375.0 / 4.0;
    f.heights = {1.0, static_cast<double>(kCapDSphereCosine), static_cast<double>((s6 - 1) / 5)};
    f.weights = {1.0 / 9.0, static_cast<double>((16 - s6) / 36), static_cast<double>((16 + s6) / 36)};
    return f;
  }
  long double lo = c, hi = 1;
  for (int i = 0; i < 200 && lo < hi; ++i) {
    const long double mid = 0.5L * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (cap_d_quintic(c, mid) > 0 ? lo : hi) = mid;
  }
  const long double t = 0.5L * (lo + hi);
  const long double c2 = c * c, c3 = c2 * c, c4 = c2 * c2, t2 = t * t, t3 = t2 * t, t4 = t2 * t2, t5 = t4 * t;
  const long double alpha =
      pow_int((t - 1) * (t + 1), 2) * (10 * t2 + t - 3 - 7 * c * t - c) /
      ((t - c) * (10 * t5 + t4 - 23 * t3 - 2 * t2 + 10 * t + 3 * c * t4 + 3 * c2 * t3 + 3 * c3 * t2 - 9 * c * t2 +
                  3 * c2 * t - 3 * c4 * t - c4 - 3 * c3 + 2 * c2 + 6 * c));
  const long double r_c = (1 - c) * (1 + c), r_t = (1 - t) * (1 + t);
  const long double Q = alpha * r_c * r_c + (1 - alpha) * r_t * r_t;
  const long double den = 16384.0L * pow_int(alpha * (1 - alpha), 3) * Q * Q * pow_int(1 + c, 2) * pow_int(1 - c, 4) *
                          pow_int(1 + t, 2) * pow_int(1 - t, 4) * pow_int(t - c, 6);
  f.value = static_cast<double>(387420489.0L / den);  // 9^9 / (2^14 ...)
  f.heights = {1.0, static_cast<double>(c), static_cast<double>(t)};
  f.weights = {1.0 / 9.0, static_cast<double>(8 * alpha / 9), static_cast<double>(8 * (1 - alpha) / 9)};
  return f;
}

// Theorem 19: the rim, the middle circle z = (1 + c)/2 and the pole.
CapClosedForm cap_e(long double c) {
  const long double c2 = c * c, c3 = c2 * c, c4 = c2 * c2;
  const long double q = 3 * c4 + 36 * c3 + 194 * c2 + 260 * c + 147;
  CapClosedForm f;
  f.theorem = "proofs/cap_es_limits.md";
  f.value = static_cast<double>(q / pow_int(1 - c, 4));
  f.heights = {static_cast<double>(c), static_cast<double>((1 + c) / 2), 1.0};
  f.weights = {static_cast<double>((3 * c3 + 31 * c2 + 73 * c + 53) / q),
               static_cast<double>(4 * (3 * c3 + 27 * c2 + 33 * c + 17) / q),
               static_cast<double>((3 * c4 + 21 * c3 + 55 * c2 + 55 * c + 26) / q)};
  return f;
}

CapClosedForm cap_s(long double c) {
  CapClosedForm f;
  f.theorem = "proofs/cap_es_limits.md";
  f.value = static_cast<double>(pow_int((3 + c) / (1 - c), 4));
  f.heights = {static_cast<double>(c), static_cast<double>((1 + c) / 2), 1.0};
  f.weights = {static_cast<double>(1 / (c + 3)), static_cast<double>(4 * (c + 1) / ((c + 3) * (c + 3))),
               static_cast<double>((c * c + c + 2) / ((c + 3) * (c + 3)))};
  return f;
}

}  // namespace

long double cap_d_quintic(long double c, long double t) {
  const long double c2 = c * c, c3 = c2 * c, c4 = c2 * c2;
  const long double k[6] = {-(c + 3) * (c + 3) * (c2 - 2),
                            -2 * c * (c + 3) * (8 * c2 - 13),
                            -(39 * c4 - 6 * c3 - 48 * c2 + 18 * c + 29),
                            2 * (24 * c3 + 3 * c2 - 54 * c - 13),
                            39 * c2 + 6 * c - 29,
                            10 * (3 * c + 1)};
  long double out = k[5];
  for (int i = 4; i >= 0; --i) out = out * t + k[i];
  return out;
}

std::optional<double> single_cap_angle(const Region& region) {
  if (region.zones.size() != 1 || !region.candidates.empty() || region.is_sphere()) return std::nullopt;
  const Zone& z = region.zones.front();
  if (z.min_tilt_deg > 0.0 || z.max_tilt_deg >= 180.0) return std::nullopt;
  return z.max_tilt_deg;
}

std::optional<CapClosedForm> cap_closed_form(CriterionKind criterion, const Region& region) {
  const auto angle = single_cap_angle(region);
  if (!angle) return std::nullopt;
  const long double c = std::cos(static_cast<long double>(*angle) * std::numbers::pi_v<long double> / 180);
  // D is invariant under every rotation; E and S under the signed permutations of the axes only.
  const bool coordinate = is_coordinate_axis(region.zones.front().axis);
  std::optional<CapClosedForm> out;
  if (criterion == CriterionKind::D && std::abs(c - kCapDSphereCosine) > kThresholdMargin) out = cap_d(c);
  if (criterion == CriterionKind::E && coordinate && c > kCapEThreshold + kThresholdMargin) out = cap_e(c);
  if (criterion == CriterionKind::S && coordinate && c > kCapSThreshold + kThresholdMargin) out = cap_s(c);
  if (out) {
    out->half_angle_deg = *angle;
    out->cosine = static_cast<double>(c);
  }
  return out;
}

}  // namespace scalcal
