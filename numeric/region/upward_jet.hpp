// Interval jets for the zone bound's hot loop (zone_sup.cpp), stored as (-lo, hi) and computed with
// the rounding mode held upward (a RoundingScope), so both ends round outward by one operation
// each: an interval sum is two additions and a double times an interval two products, with no
// sign case analysis per operation (Boost.Interval's general product branches on the signs of
// both operands; here its four products are taken branch-free). Every negated operand goes through
// negated(), which the optimiser cannot see through (-frounding-math would do the same for the
// whole unit, at 60 % more time for the zone bound under clang). The same operations run on one
// interval (double ends) or on two side by side (UpwardPair: SSE2, the x86-64 baseline), one per
// lane; each lane's ends are the single interval's to the bit (the same IEEE operations, the same
// order, a select where the scalar code branches). The zone bound takes a box's two jets, over the
// box and at its centre, in one pass.
#pragma once
#include <algorithm>
#include <array>
#include <limits>

#include <emmintrin.h>
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
template <class V>
SCALCAL_UPWARD V negated(V x) {
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

// The lanes' own operations: a double is one lane, an __m128d two.
SCALCAL_UPWARD double splat(double c, double) { return c; }
SCALCAL_UPWARD __m128d splat(double c, __m128d) { return _mm_set1_pd(c); }
// std::max(a, b) = a < b ? b : a in every lane (maxpd(x, y) = x > y ? x : y: so y = a, x = b).
SCALCAL_UPWARD double lane_max(double a, double b) { return std::max(a, b); }
SCALCAL_UPWARD __m128d lane_max(__m128d a, __m128d b) { return _mm_max_pd(b, a); }

// [lo, hi] as (neg_lo = -lo, hi): with upward rounding, an upper bound of each end.
template <class V>
struct UpwardIntervalT {
  V neg_lo, hi;
};
using UpwardInterval = UpwardIntervalT<double>;
using UpwardPair = UpwardIntervalT<__m128d>;

SCALCAL_UPWARD UpwardInterval point(double x) { return {negated(x), x}; }
SCALCAL_UPWARD double lower(UpwardInterval a) { return -a.neg_lo; }
template <class V>
SCALCAL_UPWARD UpwardIntervalT<V> operator+(UpwardIntervalT<V> a, UpwardIntervalT<V> b) {
  return {a.neg_lo + b.neg_lo, a.hi + b.hi};
}
template <class V>
SCALCAL_UPWARD UpwardIntervalT<V> operator-(UpwardIntervalT<V> a, UpwardIntervalT<V> b) {
  return {a.neg_lo + b.hi, a.hi + b.neg_lo};
}
template <class V>
SCALCAL_UPWARD UpwardIntervalT<V> operator-(UpwardIntervalT<V> a) {
  return {a.hi, a.neg_lo};
}

// c * a for a double c (exact): a scaling, with the ends swapped when c < 0.
template <class V>
SCALCAL_UPWARD UpwardIntervalT<V> scaled(double c, UpwardIntervalT<V> a) {
  if (c >= 0) return {splat(c, a.hi) * a.neg_lo, splat(c, a.hi) * a.hi};
  const V m = splat(negated(c), a.hi);
  return {m * a.hi, m * a.neg_lo};
}

// a * b: each end the extreme of the four end products, every product rounded upward.
template <class V>
SCALCAL_UPWARD UpwardIntervalT<V> operator*(UpwardIntervalT<V> a, UpwardIntervalT<V> b) {
  const V an = a.neg_lo, ah = a.hi, bn = b.neg_lo, bh = b.hi;
  const V man = negated(an), mah = negated(ah), mbn = negated(bn);
  // hi = max(lo_a lo_b, lo_a hi_b, hi_a lo_b, hi_a hi_b), with lo = -neg_lo
  const V hi = lane_max(lane_max(an * bn, man * bh), lane_max(ah * mbn, ah * bh));
  // -lo = max of the products' negations
  const V neg_lo = lane_max(lane_max(an * mbn, an * bh), lane_max(ah * bn, mah * bh));
  return {neg_lo, hi};
}

// a^2, which is never negative (tighter than a * a when a holds 0).
SCALCAL_UPWARD UpwardInterval square(UpwardInterval a) {
  if (a.neg_lo <= 0) return {a.neg_lo * negated(a.neg_lo), a.hi * a.hi};  // lo >= 0: [lo^2, hi^2]
  if (a.hi <= 0) return {negated(a.hi) * a.hi, a.neg_lo * a.neg_lo};      // hi <= 0: [hi^2, lo^2]
  return {0.0, std::max(a.neg_lo * a.neg_lo, a.hi * a.hi)};
}
// The same three cases per lane, each lane taking its case's ends.
SCALCAL_UPWARD __m128d lane_select(__m128d mask, __m128d yes, __m128d no) {
  return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
}
SCALCAL_UPWARD UpwardPair square(UpwardPair a) {
  const __m128d zero = _mm_setzero_pd();
  const __m128d nn = a.neg_lo * a.neg_lo, hh = a.hi * a.hi;
  const __m128d positive = _mm_cmple_pd(a.neg_lo, zero), negative = _mm_cmple_pd(a.hi, zero);
  const UpwardPair straddles{zero, lane_max(nn, hh)};
  const UpwardPair below{lane_select(negative, negated(a.hi) * a.hi, straddles.neg_lo),
                         lane_select(negative, nn, straddles.hi)};
  return {lane_select(positive, a.neg_lo * negated(a.neg_lo), below.neg_lo), lane_select(positive, hh, below.hi)};
}

// 1 / a for an a whose lower end is positive (everything, when it is not).
SCALCAL_UPWARD UpwardInterval reciprocal(UpwardInterval a) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (!(a.neg_lo < 0)) return {inf, inf};
  return {negated(1.0) / a.hi, 1.0 / negated(a.neg_lo)};
}
SCALCAL_UPWARD UpwardPair reciprocal(UpwardPair a) {
  const __m128d inf = _mm_set1_pd(std::numeric_limits<double>::infinity()), one = _mm_set1_pd(1.0);
  const __m128d bounded = _mm_cmplt_pd(a.neg_lo, _mm_setzero_pd());
  return {lane_select(bounded, negated(one) / a.hi, inf), lane_select(bounded, one / negated(a.neg_lo), inf)};
}

// A value with its gradient and Hessian in the chart's two coordinates (u, t).
template <class V>
struct UpwardJetT {
  UpwardIntervalT<V> v, du, dt, uu, ut, tt;
};
using UpwardJet = UpwardJetT<double>;

template <class V>
UpwardJetT<V> constant(UpwardIntervalT<V> c) {
  const UpwardIntervalT<V> zero{V{}, V{}};
  return {c, zero, zero, zero, zero, zero};
}
template <class V>
UpwardJetT<V> operator-(const UpwardJetT<V>& a, const UpwardJetT<V>& b) {
  return {a.v - b.v, a.du - b.du, a.dt - b.dt, a.uu - b.uu, a.ut - b.ut, a.tt - b.tt};
}
template <class V>
UpwardJetT<V> operator+(const UpwardJetT<V>& a, const UpwardJetT<V>& b) {
  return {a.v + b.v, a.du + b.du, a.dt + b.dt, a.uu + b.uu, a.ut + b.ut, a.tt + b.tt};
}
template <class V>
UpwardJetT<V> scaled(double c, const UpwardJetT<V>& a) {
  return {scaled(c, a.v), scaled(c, a.du), scaled(c, a.dt), scaled(c, a.uu), scaled(c, a.ut), scaled(c, a.tt)};
}
template <class V>
UpwardJetT<V> operator*(const UpwardJetT<V>& a, const UpwardJetT<V>& b) {
  return {a.v * b.v,
          a.du * b.v + a.v * b.du,
          a.dt * b.v + a.v * b.dt,
          a.uu * b.v + scaled(2.0, a.du * b.du) + a.v * b.uu,
          a.ut * b.v + a.du * b.dt + a.dt * b.du + a.v * b.ut,
          a.tt * b.v + scaled(2.0, a.dt * b.dt) + a.v * b.tt};
}
template <class V>
UpwardJetT<V> square(const UpwardJetT<V>& a) {
  return {square(a.v),
          scaled(2.0, a.v * a.du),
          scaled(2.0, a.v * a.dt),
          scaled(2.0, square(a.du) + a.v * a.uu),
          scaled(2.0, a.du * a.dt + a.v * a.ut),
          scaled(2.0, square(a.dt) + a.v * a.tt)};
}

template <class V>
UpwardJetT<V> reciprocal(const UpwardJetT<V>& a) {
  const UpwardIntervalT<V> r = reciprocal(a.v), r2 = square(r), r3 = r2 * r;
  return {r,
          -a.du * r2,
          -a.dt * r2,
          scaled(2.0, square(a.du) * r3) - a.uu * r2,
          scaled(2.0, a.du * a.dt * r3) - a.ut * r2,
          scaled(2.0, square(a.dt) * r3) - a.tt * r2};
}

// |C h(x)|^2 with h the paper's nine rows, from the jets of x's three coordinates.
template <class V>
UpwardJetT<V> norm2_jet(const Eigen::Matrix<double, Eigen::Dynamic, 9>& C, const std::array<UpwardJetT<V>, 3>& x) {
  const std::array<UpwardJetT<V>, 9> h{x[0],         x[1],        x[2],        square(x[0]), square(x[1]),
                                       square(x[2]), x[0] * x[1], x[1] * x[2], x[2] * x[0]};
  const UpwardIntervalT<V> zero{V{}, V{}};
  UpwardJetT<V> out{zero, zero, zero, zero, zero, zero};
  for (int j = 0; j < C.rows(); ++j) {
    UpwardJetT<V> y{zero, zero, zero, zero, zero, zero};
    for (int k = 0; k < 9; ++k)
      if (C(j, k) != 0.0) y = y + scaled(C(j, k), h[static_cast<std::size_t>(k)]);
    out = out + square(y);
  }
  return out;
}

// Lane `lane` (0 or 1) of a pair of intervals or jets.
inline UpwardInterval lane_of(const UpwardPair& a, int lane) {
  alignas(16) double n[2], h[2];
  _mm_store_pd(n, a.neg_lo);
  _mm_store_pd(h, a.hi);
  return {n[lane], h[lane]};
}
inline UpwardJet lane_of(const UpwardJetT<__m128d>& a, int lane) {
  return {lane_of(a.v, lane),  lane_of(a.du, lane), lane_of(a.dt, lane),
          lane_of(a.uu, lane), lane_of(a.ut, lane), lane_of(a.tt, lane)};
}
// Two intervals side by side: `first` in lane 0, `second` in lane 1.
inline UpwardPair pair_of(const UpwardInterval& first, const UpwardInterval& second) {
  return {_mm_set_pd(second.neg_lo, first.neg_lo), _mm_set_pd(second.hi, first.hi)};
}

}  // namespace scalcal
