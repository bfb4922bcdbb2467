#include "numeric/region/zone_sup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>

#include <boost/numeric/interval.hpp>

#include "numeric/model/paper9.hpp"

namespace scalcal {
namespace {

namespace bn = boost::numeric;
using I = bn::interval<double>;
using Rows = Eigen::Matrix<double, Eigen::Dynamic, 9>;

// The zone in its own frame: x = rho(z) (c(t) e1 + s(t) e2) h + z a, with rho = sqrt(1 - z^2), the
// rational half-circle c = (1 - t^2)/(1 + t^2), s = 2t/(1 + t^2), t in [-1, 1], and h = +-1 for
// the two halves. Only +, -, *, / and sqrt: every operation rounds outward, so each box's interval
// contains every direction the box describes.
struct Frame {
  Vec3 e1, e2, a;
  double z_lo, z_hi;
};

struct Box {
  double z0, z1, t0, t1;
  int half;
  double upper;
  bool operator<(const Box& o) const { return upper < o.upper; }
};

I clamp_unit(I v) { return I(std::max(-1.0, v.lower()), std::min(1.0, v.upper())); }

std::array<I, 3> position(const Frame& f, const I& z, const I& t, int half) {
  I one_minus = (I(1.0) - z) * (I(1.0) + z);
  I rho = bn::sqrt(I(std::max(0.0, one_minus.lower()), std::max(0.0, one_minus.upper())));
  // c is even and decreasing in |t|, s increasing: their ranges from the endpoints are exact.
  const double lo_abs = (t.lower() <= 0 && t.upper() >= 0) ? 0.0 : std::min(std::abs(t.lower()), std::abs(t.upper()));
  const double hi_abs = std::max(std::abs(t.lower()), std::abs(t.upper()));
  const auto c_at = [](double u) { const I x(u); return (I(1.0) - bn::square(x)) / (I(1.0) + bn::square(x)); };
  const auto s_at = [](double u) { const I x(u); return I(2.0) * x / (I(1.0) + bn::square(x)); };
  I c = clamp_unit(I(c_at(hi_abs).lower(), c_at(lo_abs).upper()));
  I s = clamp_unit(I(s_at(t.lower()).lower(), s_at(t.upper()).upper()));
  if (half < 0) {
    c = -c;
    s = -s;
  }
  const I rc = rho * c, rs = rho * s;
  std::array<I, 3> x;
  for (int i = 0; i < 3; ++i) x[static_cast<std::size_t>(i)] = rc * I(f.e1(i)) + rs * I(f.e2(i)) + z * I(f.a(i));
  return x;
}

std::array<I, 9> row(const std::array<I, 3>& x) {
  return {x[0], x[1], x[2], bn::square(x[0]), bn::square(x[1]), bn::square(x[2]), x[0] * x[1], x[1] * x[2], x[2] * x[0]};
}

I norm2(const Rows& C, const std::array<I, 9>& h) {
  I out(0.0);
  for (int j = 0; j < C.rows(); ++j) {
    I y(0.0);
    for (int k = 0; k < 9; ++k)
      if (C(j, k) != 0.0) y += I(C(j, k)) * h[static_cast<std::size_t>(k)];
    out += bn::square(y);
  }
  return out;
}

// The centred form in the zone's coordinates: F(B) within F(centre) + dF/dz(B) (Z - z_c) +
// dF/dt(B) (T - t_c) by the mean value theorem, F = f o x. Second order where the gradient
// vanishes (interior maxima), exact to first order on the rims (box edges follow the rims). Away
// from the poles only: dx/dz = a - (z / rho)(c e1 + s e2) blows up there.
I centred_bound(const Rows& C, const Frame& f, double z0, double z1, double t0, double t1, int half) {
  const I Z(z0, z1), T(t0, t1);
  I one_minus = (I(1.0) - Z) * (I(1.0) + Z);
  if (!(one_minus.lower() > 1e-6)) return I::whole();
  const I rho = bn::sqrt(one_minus);
  const I q = I(1.0) + bn::square(T);
  I c = (I(1.0) - bn::square(T)) / q, s = I(2.0) * T / q;
  I dc = I(-4.0) * T / bn::square(q), ds = I(2.0) * (I(1.0) - bn::square(T)) / bn::square(q);
  if (half < 0) {
    c = -c;
    s = -s;
    dc = -dc;
    ds = -ds;
  }
  const I drho = -Z / rho;
  std::array<I, 3> x, xz, xt;
  for (int i = 0; i < 3; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    x[k] = rho * (c * I(f.e1(i)) + s * I(f.e2(i))) + Z * I(f.a(i));
    xz[k] = drho * (c * I(f.e1(i)) + s * I(f.e2(i))) + I(f.a(i));
    xt[k] = rho * (dc * I(f.e1(i)) + ds * I(f.e2(i)));
  }
  // dh/dz and dh/dt by the product rule on h = (x, x_i^2, x_i x_j).
  const auto dh = [&](const std::array<I, 3>& d) {
    return std::array<I, 9>{d[0], d[1], d[2], I(2.0) * x[0] * d[0], I(2.0) * x[1] * d[1], I(2.0) * x[2] * d[2],
                            d[0] * x[1] + x[0] * d[1], d[1] * x[2] + x[1] * d[2], d[2] * x[0] + x[2] * d[0]};
  };
  const std::array<I, 9> h = row(x), hz = dh(xz), ht = dh(xt);
  I Fz(0.0), Ft(0.0);
  for (int j = 0; j < C.rows(); ++j) {
    I y(0.0), yz(0.0), yt(0.0);
    for (int k = 0; k < 9; ++k) {
      const I cjk(C(j, k));
      const std::size_t kk = static_cast<std::size_t>(k);
      y += cjk * h[kk];
      yz += cjk * hz[kk];
      yt += cjk * ht[kk];
    }
    Fz += I(2.0) * y * yz;
    Ft += I(2.0) * y * yt;
  }
  const double zc = 0.5 * (z0 + z1), tc = 0.5 * (t0 + t1);
  const I at_centre = norm2(C, row(position(f, I(zc), I(tc), half)));
  return at_centre + Fz * (Z - I(zc)) + Ft * (T - I(tc));
}

Vec3 point(const Frame& f, double z, double t, int half) {
  const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double c = half * (1 - t * t) / (1 + t * t), s = half * 2 * t / (1 + t * t);
  return (rho * c * f.e1 + rho * s * f.e2 + z * f.a).normalized();
}

double value_at(const Rows& C, const Vec3& x) { return (C * Paper9Model::row(x)).squaredNorm(); }

Frame frame_of(const Zone& zone) {
  Frame f;
  f.a = zone.axis.normalized();
  const Vec3 helper = std::abs(f.a.z()) < 0.9 ? Vec3(0, 0, 1) : Vec3(1, 0, 0);
  f.e1 = helper.cross(f.a).normalized();
  f.e2 = f.a.cross(f.e1);
  const double deg = std::numbers::pi / 180.0;
  // Widened outward by a few ulps: a slightly larger zone only makes the bound safer.
  f.z_lo = std::max(-1.0, std::cos(zone.max_tilt_deg * deg) - 4 * std::numeric_limits<double>::epsilon());
  f.z_hi = std::min(1.0, std::cos(zone.min_tilt_deg * deg) + 4 * std::numeric_limits<double>::epsilon());
  return f;
}

void pick_near_maxima(std::vector<std::pair<double, Vec3>>& seen, SupBound& out) {
  std::sort(seen.begin(), seen.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  const double cos_apart = std::cos(std::numbers::pi / 180.0);
  for (const auto& [v, x] : seen) {
    if (out.near_maxima.size() >= 16) break;
    if (std::none_of(out.near_maxima.begin(), out.near_maxima.end(), [&](const Vec3& y) { return y.dot(x) > cos_apart; }))
      out.near_maxima.push_back(x);
  }
}

}  // namespace

SupBound sup_norm2_over_zone(const Rows& C, const Zone& zone, double rel_tol, long box_budget) {
  const Frame f = frame_of(zone);
  SupBound out;
  out.lower = -1;
  std::priority_queue<Box> queue;
  std::vector<std::pair<double, Vec3>> seen;
  const auto visit = [&](double z0, double z1, double t0, double t1, int half) {
    ++out.boxes;
    const double natural = norm2(C, row(position(f, I(z0, z1), I(t0, t1), half))).upper();
    const double bound = std::min(natural, centred_bound(C, f, z0, z1, t0, t1, half).upper());
    const Vec3 centre = point(f, 0.5 * (z0 + z1), 0.5 * (t0 + t1), half);
    const double v = value_at(C, centre);
    if (v > out.lower) {
      out.lower = v;
      out.argmax = centre;
    }
    if (v >= (1 - 1e-4) * out.lower) seen.emplace_back(v, centre);
    queue.push(Box{z0, z1, t0, t1, half, bound});
  };
  // Start from a modest grid so that every ring and both halves are explored at once.
  const int nz = 16, nt = 8;
  for (int half : {1, -1})
    for (int i = 0; i < nz; ++i)
      for (int j = 0; j < nt; ++j)
        visit(f.z_lo + (f.z_hi - f.z_lo) * i / nz, i + 1 == nz ? f.z_hi : f.z_lo + (f.z_hi - f.z_lo) * (i + 1) / nz,
              -1.0 + 2.0 * j / nt, j + 1 == nt ? 1.0 : -1.0 + 2.0 * (j + 1) / nt, half);
  while (true) {
    const Box b = queue.top();
    out.upper = b.upper;
    if (b.upper - out.lower <= rel_tol * std::abs(b.upper) || out.boxes >= box_budget) break;
    queue.pop();
    // Split the side that moves x most: dx/dz ~ 1/rho near the poles, dx/dt ~ 2 rho.
    const double zm = 0.5 * (b.z0 + b.z1), tm = 0.5 * (b.t0 + b.t1);
    const double rho = std::sqrt(std::max(1e-300, 1 - std::min(b.z0 * b.z0, b.z1 * b.z1)));
    const double z_side = (b.z1 - b.z0) / std::max(rho, std::sqrt(b.z1 - b.z0)), t_side = 2 * rho * (b.t1 - b.t0);
    if (z_side >= t_side) {
      visit(b.z0, zm, b.t0, b.t1, b.half);
      visit(zm, b.z1, b.t0, b.t1, b.half);
    } else {
      visit(b.z0, b.z1, b.t0, tm, b.half);
      visit(b.z0, b.z1, tm, b.t1, b.half);
    }
  }
  std::erase_if(seen, [&](const auto& p) { return p.first < (1 - 1e-3) * out.lower; });
  pick_near_maxima(seen, out);
  return out;
}

SupBound sup_norm2_over_points(const Rows& C, const std::vector<Vec3>& points) {
  SupBound out;
  out.lower = -1;
  std::vector<std::pair<double, Vec3>> seen;
  for (const Vec3& x : points) {
    const I bound = norm2(C, row({I(x(0)), I(x(1)), I(x(2))}));
    out.upper = std::max(out.upper, bound.upper());
    const double v = value_at(C, x);
    if (v > out.lower) {
      out.lower = v;
      out.argmax = x;
    }
    seen.emplace_back(v, x);
  }
  out.boxes = static_cast<long>(points.size());
  pick_near_maxima(seen, out);
  return out;
}

}  // namespace scalcal
