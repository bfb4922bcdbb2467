// A proven upper bound on sup |C h(x)|^2 over a zone (zone_sup.hpp).
#include "numeric/region/zone_sup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>

#include "numeric/model/paper9.hpp"
#include "numeric/region/interval.hpp"
#include "numeric/region/upward_jet.hpp"

namespace scalcal {
namespace {

namespace bn = boost::numeric;
using I = Interval;
using Rows = Eigen::Matrix<double, Eigen::Dynamic, 9>;

using Jet = UpwardJet;

// One piece of a zone: tilts within 90 degrees of `axis`, as u = tan(tilt / 2) in [u0, u1] (a
// subset of [0, 1]); azimuth on two rational half circles, c = (1 - t^2) / (1 + t^2),
// s = 2 t / (1 + t^2), t in [-1, 1], signed by `half`. Only +, -, *, /: every operation rounds
// outward, so each box's enclosure holds for every direction it describes, the pole included.
struct Chart {
  Vec3 axis, e1, e2;
  double u0, u1;
};

UpwardInterval upward(const I& a) { return {-a.lower(), a.upper()}; }

// x(u, t) with its derivatives, on the box U x T (or a point), for one box or two side by side.
template <class V>
std::array<UpwardJetT<V>, 3> position(const Chart& ch, UpwardIntervalT<V> U, UpwardIntervalT<V> T, int half) {
  using J = UpwardJetT<V>;
  const UpwardIntervalT<V> zero{V{}, V{}}, one_i{splat(-1.0, V{}), splat(1.0, V{})};
  const J u{U, one_i, zero, zero, zero, zero}, t{T, zero, one_i, zero, zero, zero};
  const J one = constant(one_i), two_u = scaled(2.0, u), two_t = scaled(2.0, t);
  const J ru = reciprocal(one + square(u)), rt = reciprocal(one + square(t));
  const J cos_tilt = (one - square(u)) * ru, sin_tilt = two_u * ru;
  const J c = scaled(static_cast<double>(half), (one - square(t)) * rt),
          s = scaled(static_cast<double>(half), two_t * rt);
  const J sc = sin_tilt * c, ss = sin_tilt * s;
  std::array<J, 3> x;
  for (int i = 0; i < 3; ++i)
    x[static_cast<std::size_t>(i)] = scaled(ch.e1(i), sc) + scaled(ch.e2(i), ss) + scaled(ch.axis(i), cos_tilt);
  return x;
}

// The midpoint in the current (upward) rounding: any double near the middle will do.
double mid(const I& x) { return 0.5 * x.lower() + 0.5 * x.upper(); }
double mid(const UpwardInterval& x) { return 0.5 * lower(x) + 0.5 * x.hi; }
double radius(const UpwardInterval& x) { return 0.5 * (x.hi + x.neg_lo); }

// max over s in [-R, R] of alpha + beta s + gamma s^2 (gamma exact), as a proven upper bound.
double max_1d(const I& alpha, const I& beta, double gamma, double R) {
  const I r(R);
  double out = std::max((alpha + beta * r + I(gamma) * bn::square(r)).upper(),
                        (alpha - beta * r + I(gamma) * bn::square(r)).upper());
  if (gamma < 0) {
    const double vertex = std::abs(mid(beta)) / (-2 * gamma);
    if (vertex < R * (1 + 1e-9) + 1e-300) out = std::max(out, (alpha - bn::square(beta) / (I(4.0) * I(gamma))).upper());
  }
  return out;
}

// A proven upper bound on max over |d_u| <= ru, |d_t| <= rt of q(d) = g . d + d^T H d / 2 (g, H
// exact doubles): on the four edges, and at the interior stationary point when H may be negative
// definite.
double max_quadratic(double gu, double gt, double a, double b, double d, double ru, double rt) {
  double out = -std::numeric_limits<double>::infinity();
  for (double su : {-1.0, 1.0}) {  // d_u = su ru: alpha + beta d_t + (d / 2) d_t^2
    const I du = I(su) * I(ru);
    out = std::max(out, max_1d(I(gu) * du + I(0.5) * I(a) * bn::square(du), I(gt) + I(b) * du, 0.5 * d, rt));
  }
  for (double st : {-1.0, 1.0}) {
    const I dt = I(st) * I(rt);
    out = std::max(out, max_1d(I(gt) * dt + I(0.5) * I(d) * bn::square(dt), I(gu) + I(b) * dt, 0.5 * a, ru));
  }
  const I det = I(a) * I(d) - bn::square(I(b));
  if (a < 0 && det.upper() > 0) {  // H may be negative definite: an interior maximum is possible
    if (!(det.lower() > 0)) {      // undecided: q <= |g| . r + (a+ ru^2 + 2 |b| ru rt + d+ rt^2) / 2
      const I crude = I(std::abs(gu)) * I(ru) + I(std::abs(gt)) * I(rt) +
                      I(0.5) * (I(std::max(a, 0.0)) * bn::square(I(ru)) + I(2.0 * std::abs(b)) * I(ru) * I(rt) +
                                I(std::max(d, 0.0)) * bn::square(I(rt)));
      return std::max(out, crude.upper());
    }
    // d* = -H^-1 g; skipped when certainly outside the box (the maximum is then on an edge).
    const double xu = -(d * gu - b * gt) / mid(det), xt = -(a * gt - b * gu) / mid(det);
    if (std::abs(xu) <= ru * (1 + 1e-6) && std::abs(xt) <= rt * (1 + 1e-6)) {
      // -g^T H^-1 g / 2 = -(d gu^2 - 2 b gu gt + a gt^2) / (2 det)
      const I num = I(d) * bn::square(I(gu)) - I(2.0) * I(b) * I(gu) * I(gt) + I(a) * bn::square(I(gt));
      out = std::max(out, (-num / (I(2.0) * det)).upper());
    }
  }
  return out;
}

struct Box {
  double u0, u1, t0, t1;
  int half;
  double upper;
  bool operator<(const Box& o) const { return upper < o.upper; }
};

// The bound on one box: the smaller of the natural enclosure and the second-order Taylor form
// f(c) + g.d + d^T H(B) d / 2 around the centre c.
double box_bound(const Rows& C, const Chart& ch, const Box& b) {
  // The jets over the box (lane 0) and at its centre (lane 1), in one pass.
  const double cu = 0.5 * (b.u0 + b.u1), ct = 0.5 * (b.t0 + b.t1);
  const UpwardPair U = pair_of(upward(I(b.u0, b.u1)), upward(I(cu))), T = pair_of(upward(I(b.t0, b.t1)), upward(I(ct)));
  const UpwardJetT<__m128d> both = norm2_jet(C, position(ch, U, T, b.half));
  const Jet over = lane_of(both, 0), at = lane_of(both, 1);
  // Half-widths rounded up so that [c - r, c + r] covers the box.
  const double ru =
      (I(b.u1) - I(cu)).upper() > (I(cu) - I(b.u0)).upper() ? (I(b.u1) - I(cu)).upper() : (I(cu) - I(b.u0)).upper();
  const double rt =
      (I(b.t1) - I(ct)).upper() > (I(ct) - I(b.t0)).upper() ? (I(b.t1) - I(ct)).upper() : (I(ct) - I(b.t0)).upper();
  const double gu = mid(at.du), gt = mid(at.dt);
  const double a = mid(over.uu), hb = mid(over.ut), d = mid(over.tt);
  // What the midpoints leave out: the gradient's enclosure at c and the Hessian's over the box.
  I spread = I(radius(at.du)) * I(ru) + I(radius(at.dt)) * I(rt);
  spread += I(0.5) * (I(radius(over.uu)) * bn::square(I(ru)) + I(2.0) * I(radius(over.ut)) * I(ru) * I(rt) +
                      I(radius(over.tt)) * bn::square(I(rt)));
  const double taylor = (I(at.v.hi) + I(max_quadratic(gu, gt, a, hb, d, ru, rt)) + spread).upper();
  return std::min(over.v.hi, taylor);
}

Vec3 point(const Chart& ch, double u, double t, int half) {
  const double ct = (1 - u * u) / (1 + u * u), st = 2 * u / (1 + u * u);
  const double c = half * (1 - t * t) / (1 + t * t), s = half * 2 * t / (1 + t * t);
  return (st * (c * ch.e1 + s * ch.e2) + ct * ch.axis).normalized();
}

double value_at(const Rows& C, const Vec3& x) { return (C * Paper9Model::row(x)).squaredNorm(); }

// tan(tilt / 2) for a tilt in [0, 90] degrees, rounded outward by a few ulps (a slightly larger
// zone only makes the bound safer); 0 and 90 degrees are exact.
double half_tangent(double tilt_deg, bool lower) {
  if (tilt_deg <= 0) return 0.0;
  if (tilt_deg >= 90) return 1.0;
  const double v = std::tan(tilt_deg * std::numbers::pi / 360.0);
  const double widen = 4 * std::numeric_limits<double>::epsilon() * v;
  return std::clamp(lower ? v - widen : v + widen, 0.0, 1.0);
}

// The zone as charts of tilts within 90 degrees of +axis and of -axis.
std::vector<Chart> charts_of(const Zone& zone) {
  std::vector<Chart> out;
  const Vec3 a = zone.axis.normalized();
  const Vec3 helper = std::abs(a.x()) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 e1 = (helper - helper.dot(a) * a).normalized(), e2 = a.cross(e1);
  if (zone.min_tilt_deg < 90)
    out.push_back(
        {a, e1, e2, half_tangent(zone.min_tilt_deg, true), half_tangent(std::min(zone.max_tilt_deg, 90.0), false)});
  if (zone.max_tilt_deg > 90)
    out.push_back({Vec3(-a), e2, e1, half_tangent(180 - zone.max_tilt_deg, true),
                   half_tangent(180 - std::max(zone.min_tilt_deg, 90.0), false)});
  return out;
}

}  // namespace

SupBound sup_norm2_over_zone(const Rows& C, const Zone& zone, double rel_tol, long box_budget) {
  const RoundingScope rounding;
  SupBound out;
  out.lower = -1;
  std::vector<Chart> charts = charts_of(zone);
  struct Entry {
    Box box;
    int chart;
    bool operator<(const Entry& o) const { return box < o.box; }
  };
  std::priority_queue<Entry> queue;
  const auto visit = [&](int k, Box b) {
    const Chart& ch = charts[static_cast<std::size_t>(k)];
    ++out.boxes;
    b.upper = box_bound(C, ch, b);
    const Vec3 centre = point(ch, 0.5 * (b.u0 + b.u1), 0.5 * (b.t0 + b.t1), b.half);
    const double v = value_at(C, centre);
    if (v > out.lower) {
      out.lower = v;
      out.argmax = centre;
    }
    queue.push({b, k});
  };
  constexpr int kStart = 8;
  for (int k = 0; k < static_cast<int>(charts.size()); ++k) {
    const Chart& ch = charts[static_cast<std::size_t>(k)];
    for (int half : {1, -1})
      for (int i = 0; i < kStart; ++i)
        for (int j = 0; j < kStart; ++j)
          visit(k, Box{ch.u0 + (ch.u1 - ch.u0) * i / kStart,
                       i + 1 == kStart ? ch.u1 : ch.u0 + (ch.u1 - ch.u0) * (i + 1) / kStart, -1.0 + 2.0 * j / kStart,
                       j + 1 == kStart ? 1.0 : -1.0 + 2.0 * (j + 1) / kStart, half, 0.0});
  }
  while (true) {
    const Entry e = queue.top();
    out.upper = e.box.upper;
    if (e.box.upper - out.lower <= rel_tol * std::abs(e.box.upper) || out.boxes >= box_budget) break;
    queue.pop();
    const Box& b = e.box;
    // Split the side that moves x most: |dx/du| = 2 / (1 + u^2), |dx/dt| = sin(tilt) 2 / (1 + t^2).
    const double tmin = (b.t0 <= 0 && b.t1 >= 0) ? 0.0 : std::min(std::abs(b.t0), std::abs(b.t1));
    const double u_side = 2 * (b.u1 - b.u0) / (1 + b.u0 * b.u0);
    const double t_side = 2 * b.u1 / (1 + b.u1 * b.u1) * 2 * (b.t1 - b.t0) / (1 + tmin * tmin);
    if (u_side >= t_side) {
      const double m = 0.5 * (b.u0 + b.u1);
      visit(e.chart, Box{b.u0, m, b.t0, b.t1, b.half, 0.0});
      visit(e.chart, Box{m, b.u1, b.t0, b.t1, b.half, 0.0});
    } else {
      const double m = 0.5 * (b.t0 + b.t1);
      visit(e.chart, Box{b.u0, b.u1, b.t0, m, b.half, 0.0});
      visit(e.chart, Box{b.u0, b.u1, m, b.t1, b.half, 0.0});
    }
  }
  return out;
}

SupBound sup_norm2_over_points(const Rows& C, const std::vector<Vec3>& points) {
  const RoundingScope rounding;
  SupBound out;
  out.lower = -1;
  for (const Vec3& x : points) {
    const Jet j = norm2_jet<double>(C, {constant(point(x(0))), constant(point(x(1))), constant(point(x(2)))});
    out.upper = std::max(out.upper, j.v.hi);
    const double v = value_at(C, x);
    if (v > out.lower) {
      out.lower = v;
      out.argmax = x;
    }
  }
  out.boxes = static_cast<long>(points.size());
  return out;
}

}  // namespace scalcal
