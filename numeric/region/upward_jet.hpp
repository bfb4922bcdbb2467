// Interval jets for the zone bound's hot loop (zone_sup.cpp), stored as (-lo, hi) and computed with
// the rounding mode held upward (a RoundingScope), so both ends round outward by one operation
// each: an interval sum is two additions and a double times an interval two products, with no
// sign case analysis per operation (Boost.Interval's general product branches on the signs of
// both operands; here its four products are taken branch-free). Every negated operand goes through
// negated(), which the optimiser cannot see through (-frounding-math would do the same for the
// whole unit, at 60 % more time for the zone bound under clang).
#pragma once
#include <algorithm>
#include <array>
#include <limits>

#include <Eigen/Core>

namespace scalcal {

// The interval operations are inlined into the jets' (each is a few instructions; a call costs more).
#if defined(__GNUC__)
#define SCALCAL_UPWARD inline __attribute__((always_inline))
#else
#define SCALCAL_UPWARD inline
#endif

// -x, hidden from the optimiser: under round-to-nearest (-a) * b equals -(a * b), and a compiler may
// rewrite one as the other; rounded upward they differ (the first bounds the product from above, the
// second from below). The empty asm makes the negated value opaque, so the product is kept as written.
SCALCAL_UPWARD double negated(double x) {
  x = -x;
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  asm("" : "+x"(x));
#elif defined(__GNUC__)
  asm("" : "+r"(x));
#else
  volatile double v = x;
  x = v;
#endif
  return x;
}

// [lo, hi] as (neg_lo = -lo, hi): with upward rounding, an upper bound of each end.
struct UpwardInterval {
  double neg_lo, hi;
};

SCALCAL_UPWARD UpwardInterval point(double x) { return {negated(x), x}; }
SCALCAL_UPWARD double lower(UpwardInterval a) { return -a.neg_lo; }
SCALCAL_UPWARD UpwardInterval operator+(UpwardInterval a, UpwardInterval b) {
  return {a.neg_lo + b.neg_lo, a.hi + b.hi};
}
SCALCAL_UPWARD UpwardInterval operator-(UpwardInterval a, UpwardInterval b) {
  return {a.neg_lo + b.hi, a.hi + b.neg_lo};
}
SCALCAL_UPWARD UpwardInterval operator-(UpwardInterval a) { return {a.hi, a.neg_lo}; }

// c * a for a double c (exact): a scaling, with the ends swapped when c < 0.
SCALCAL_UPWARD UpwardInterval scaled(double c, UpwardInterval a) {
  if (c >= 0) return {c * a.neg_lo, c * a.hi};
  const double m = negated(c);
  return {m * a.hi, m * a.neg_lo};
}

// a * b: each end the extreme of the four end products, every product rounded upward.
SCALCAL_UPWARD UpwardInterval operator*(UpwardInterval a, UpwardInterval b) {
  const double an = a.neg_lo, ah = a.hi, bn = b.neg_lo, bh = b.hi;
  const double man = negated(an), mah = negated(ah), mbn = negated(bn);
  // hi = max(lo_a lo_b, lo_a hi_b, hi_a lo_b, hi_a hi_b), with lo = -neg_lo
  const double hi = std::max(std::max(an * bn, man * bh), std::max(ah * mbn, ah * bh));
  // -lo = max of the products' negations
  const double neg_lo = std::max(std::max(an * mbn, an * bh), std::max(ah * bn, mah * bh));
  return {neg_lo, hi};
}

// a^2, which is never negative (tighter than a * a when a holds 0).
SCALCAL_UPWARD UpwardInterval square(UpwardInterval a) {
  if (a.neg_lo <= 0) return {a.neg_lo * negated(a.neg_lo), a.hi * a.hi};  // lo >= 0: [lo^2, hi^2]
  if (a.hi <= 0) return {negated(a.hi) * a.hi, a.neg_lo * a.neg_lo};      // hi <= 0: [hi^2, lo^2]
  return {0.0, std::max(a.neg_lo * a.neg_lo, a.hi * a.hi)};
}

// 1 / a for an a whose lower end is positive (everything, when it is not).
inline UpwardInterval reciprocal(UpwardInterval a) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (!(a.neg_lo < 0)) return {inf, inf};
  return {negated(1.0) / a.hi, 1.0 / negated(a.neg_lo)};
}

// A value with its gradient and Hessian in the chart's two coordinates (u, t).
struct UpwardJet {
  UpwardInterval v, du, dt, uu, ut, tt;
};

inline UpwardJet constant(UpwardInterval c) {
  const UpwardInterval zero{0.0, 0.0};
  return {c, zero, zero, zero, zero, zero};
}
inline UpwardJet operator-(const UpwardJet& a, const UpwardJet& b) {
  return {a.v - b.v, a.du - b.du, a.dt - b.dt, a.uu - b.uu, a.ut - b.ut, a.tt - b.tt};
}
inline UpwardJet operator+(const UpwardJet& a, const UpwardJet& b) {
  return {a.v + b.v, a.du + b.du, a.dt + b.dt, a.uu + b.uu, a.ut + b.ut, a.tt + b.tt};
}
inline UpwardJet scaled(double c, const UpwardJet& a) {
  return {scaled(c, a.v), scaled(c, a.du), scaled(c, a.dt), scaled(c, a.uu), scaled(c, a.ut), scaled(c, a.tt)};
}
inline UpwardJet operator*(const UpwardJet& a, const UpwardJet& b) {
  return {a.v * b.v,
          a.du * b.v + a.v * b.du,
          a.dt * b.v + a.v * b.dt,
          a.uu * b.v + scaled(2.0, a.du * b.du) + a.v * b.uu,
          a.ut * b.v + a.du * b.dt + a.dt * b.du + a.v * b.ut,
          a.tt * b.v + scaled(2.0, a.dt * b.dt) + a.v * b.tt};
}
inline UpwardJet square(const UpwardJet& a) {
  return {square(a.v),
          scaled(2.0, a.v * a.du),
          scaled(2.0, a.v * a.dt),
          scaled(2.0, square(a.du) + a.v * a.uu),
          scaled(2.0, a.du * a.dt + a.v * a.ut),
          scaled(2.0, square(a.dt) + a.v * a.tt)};
}

inline UpwardJet reciprocal(const UpwardJet& a) {
  const UpwardInterval r = reciprocal(a.v), r2 = square(r), r3 = r2 * r;
  return {r,
          -a.du * r2,
          -a.dt * r2,
          scaled(2.0, square(a.du) * r3) - a.uu * r2,
          scaled(2.0, a.du * a.dt * r3) - a.ut * r2,
          scaled(2.0, square(a.dt) * r3) - a.tt * r2};
}

// |C h(x)|^2 with h the paper's nine rows, from the jets of x's three coordinates.
inline UpwardJet norm2_jet(const Eigen::Matrix<double, Eigen::Dynamic, 9>& C, const std::array<UpwardJet, 3>& x) {
  const std::array<UpwardJet, 9> h{x[0],         x[1],        x[2],        square(x[0]), square(x[1]),
                                   square(x[2]), x[0] * x[1], x[1] * x[2], x[2] * x[0]};
  const UpwardInterval zero{0.0, 0.0};
  UpwardJet out{zero, zero, zero, zero, zero, zero};
  for (int j = 0; j < C.rows(); ++j) {
    UpwardJet y{zero, zero, zero, zero, zero, zero};
    for (int k = 0; k < 9; ++k)
      if (C(j, k) != 0.0) y = y + scaled(C(j, k), h[static_cast<std::size_t>(k)]);
    out = out + square(y);
  }
  return out;
}

}  // namespace scalcal
