// Local ascent on the sphere inside a region: trust-region Newton steps in the tangent plane, with
// the gradient and Hessian from central differences (f is a cheap polynomial), so a peak on a
// nearly flat ridge is reached in a few steps where a pattern search would creep along it. A step
// that leaves the region is pulled back onto the rim of the zone the point is in, and on a rim
// where f rises outward the step follows the rim. Used to place positions where a sensitivity
// function peaks (region limits) or where a criterion gains most (augment).
#pragma once
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <Eigen/Dense>

#include "numeric/region/region.hpp"
#include "numeric/region/region_synthesis.hpp"

namespace scalcal {

template <class F>
Vec3 climb(const F& f, Vec3 x, const Region& region, double start_deg = 1.0, double end_deg = 1e-9) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  const auto inside = [&](Vec3 y, const Vec3& from) -> std::optional<Vec3> {
    if (region.contains(y, 1e-9)) return y;
    const int z = region.deepest_zone(from);
    if (z < 0) return std::nullopt;
    y = clamp_to_zone(region.zones[static_cast<std::size_t>(z)], y);
    if (!region.contains(y, 1e-9)) return std::nullopt;
    return y;
  };
  double radius = start_deg * kDeg, best = f(x);
  for (int it = 0; it < 200 && radius > end_deg * kDeg; ++it) {
    // Named copies, not a structured binding: clang (C++20 before 16) cannot capture bindings.
    const auto frame = azimuth_frame(x);
    const Vec3 e1 = frame.first, e2 = frame.second;
    const double h = std::clamp(0.1 * radius, 1e-6, 1e-3);
    const auto at = [&](double a, double b) { return f((x + a * e1 + b * e2).normalized()); };
    const double f0 = best, fpa = at(h, 0), fma = at(-h, 0), fpb = at(0, h), fmb = at(0, -h);
    Eigen::Vector2d g((fpa - fma) / (2 * h), (fpb - fmb) / (2 * h));
    Eigen::Matrix2d H;
    H(0, 0) = (fpa - 2 * f0 + fma) / (h * h);
    H(1, 1) = (fpb - 2 * f0 + fmb) / (h * h);
    H(0, 1) = H(1, 0) = (at(h, h) - at(h, -h) - at(-h, h) + at(-h, -h)) / (4 * h * h);
    // On a rim where f rises outward, only moves along the rim can gain.
    const int zi = region.deepest_zone(x);
    if (zi >= 0) {
      const Zone& zone = region.zones[static_cast<std::size_t>(zi)];
      const double t = zone.tilt_deg(x);
      const Vec3 away = (x.dot(zone.axis) * x - zone.axis);  // tangent, towards larger tilt
      Eigen::Vector2d out(away.dot(e1), away.dot(e2));
      const bool at_max = t >= zone.max_tilt_deg - 1e-9, at_min = t <= zone.min_tilt_deg + 1e-9;
      if ((at_max || at_min) && out.norm() > 1e-12) {
        out.normalize();
        if (at_min) out = -out;
        if (g.dot(out) > 0) {
          const Eigen::Vector2d along(-out(1), out(0));
          const double ga = g.dot(along), ha = along.dot(H * along);
          g = ga * along;
          H = ha * along * along.transpose() - 1e3 * std::abs(ha + 1) * out * out.transpose();
        }
      }
    }
    Eigen::Vector2d p;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(H);
    if (eig.eigenvalues()(1) < 0)
      p = -H.ldlt().solve(g);
    else
      p = g.norm() > 0 ? Eigen::Vector2d(g * (radius / g.norm())) : Eigen::Vector2d::Zero();
    if (p.norm() > radius) p *= radius / p.norm();
    if (p.norm() < 1e-15) break;
    const auto y = inside((x + p(0) * e1 + p(1) * e2).normalized(), x);
    const double fy = y ? f(*y) : -INFINITY;
    if (fy > best) {
      x = *y;
      best = fy;
      radius = std::min(2 * radius, 10 * kDeg);
      if (p.norm() < end_deg * kDeg) break;
    } else {
      radius = 0.25 * std::min(radius, p.norm());
    }
  }
  return x;
}

// The same along one half-meridian of a zone (azimuth fixed, tilt in the zone's range): where a
// meridian-reduced region's optimal measure lives (Region::meridian_reduced).
template <class F>
double climb_meridian(const F& f, const Zone& zone, double azimuth, double tilt, double end_deg = 1e-9) {
  const auto g = [&](double t) {
    return f(zone_position(zone, std::clamp(t, zone.min_tilt_deg, zone.max_tilt_deg), azimuth));
  };
  double radius = 1.0, best = g(tilt);
  for (int it = 0; it < 200 && radius > end_deg; ++it) {
    const double h = std::clamp(0.1 * radius, 1e-5, 1e-2);
    const double gp = g(tilt + h), gm = g(tilt - h);
    const double d1 = (gp - gm) / (2 * h), d2 = (gp - 2 * best + gm) / (h * h);
    double step = d2 < 0 ? -d1 / d2 : (d1 > 0 ? radius : -radius);
    step = std::clamp(step, -radius, radius);
    const double next = std::clamp(tilt + step, zone.min_tilt_deg, zone.max_tilt_deg);
    if (next == tilt) break;
    const double v = g(next);
    if (v > best) {
      best = v;
      const double moved = std::abs(next - tilt);
      tilt = next;
      radius = std::min(2 * radius, 10.0);
      if (moved < end_deg) break;
    } else {
      radius = 0.25 * std::min(radius, std::abs(next - tilt));
    }
  }
  return tilt;
}

}  // namespace scalcal
