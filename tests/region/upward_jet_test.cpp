// The zone bound's upward intervals (numeric/region/upward_jet.hpp) against Boost.Interval's
// (an independent implementation, with a sign case analysis) and against exact error terms: every
// end must bound the true set, and the ends must be Boost's to the bit.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "numeric/region/interval.hpp"
#include "numeric/region/upward_jet.hpp"

namespace scalcal {
namespace {

// Intervals of every sign pattern (both ends negative, straddling zero, both positive, a point,
// an end at zero), with ends of varied magnitude so that products round.
UpwardInterval random_interval(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-20, 20), shape(0, 5);
  double a = std::ldexp(mantissa(rng), exponent(rng)), b = std::ldexp(mantissa(rng), exponent(rng));
  if (a > b) std::swap(a, b);
  switch (shape(rng)) {
    case 0:
      b = a;
      break;  // a point
    case 1:
      a = 0.0;
      break;  // lower end at zero
    case 2:
      b = 0.0;
      break;  // upper end at zero
    case 3:
      b = std::abs(b);
      a = -std::abs(a);
      break;  // straddles zero
    default:
      break;
  }
  if (a > b) std::swap(a, b);
  return {-a, b};
}

Interval boost_of(const UpwardInterval& a) { return Interval(-a.neg_lo, a.hi); }

// x * y exactly as hi + lo (Dekker's product by fma), checked against a proven bound `upper`.
bool product_below(double x, double y, double upper) {
  const double p = x * y;  // rounded upward (the scope is alive)
  const double e = std::fma(x, y, -p);
  return p < upper || (p == upper && e <= 0);
}

TEST(UpwardJet, ProductsAndSquaresAreBoostsToTheBitAndEncloseEveryEndProduct) {
  const RoundingScope rounding;
  std::mt19937_64 rng(20261126);
  for (int trial = 0; trial < 200000; ++trial) {
    const UpwardInterval a = random_interval(rng), b = random_interval(rng);
    const UpwardInterval p = a * b, s = square(a), sum = a + b, diff = a - b;
    const Interval bp = boost_of(a) * boost_of(b), bs = boost::numeric::square(boost_of(a));
    const Interval bsum = boost_of(a) + boost_of(b), bdiff = boost_of(a) - boost_of(b);
    ASSERT_EQ(-p.neg_lo, bp.lower()) << trial;
    ASSERT_EQ(p.hi, bp.upper()) << trial;
    ASSERT_EQ(-s.neg_lo, bs.lower()) << trial;
    ASSERT_EQ(s.hi, bs.upper()) << trial;
    ASSERT_EQ(-sum.neg_lo, bsum.lower()) << trial;
    ASSERT_EQ(sum.hi, bsum.upper()) << trial;
    ASSERT_EQ(-diff.neg_lo, bdiff.lower()) << trial;
    ASSERT_EQ(diff.hi, bdiff.upper()) << trial;
    // Every product of ends lies within [lo, hi], exactly (not only after rounding).
    for (const double x : {-a.neg_lo, a.hi})
      for (const double y : {-b.neg_lo, b.hi}) {
        ASSERT_TRUE(product_below(x, y, p.hi)) << trial;
        ASSERT_TRUE(product_below(-x, y, p.neg_lo)) << trial;
      }
    const double c = std::ldexp(std::uniform_real_distribution<double>(-1.0, 1.0)(rng), 3);
    const UpwardInterval cs = scaled(c, a);
    const Interval bcs = c * boost_of(a);
    ASSERT_EQ(-cs.neg_lo, bcs.lower()) << trial;
    ASSERT_EQ(cs.hi, bcs.upper()) << trial;
  }
}

TEST(UpwardJet, ReciprocalOfAPositiveIntervalIsBoosts) {
  const RoundingScope rounding;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> end(1.0, 3.0);
  for (int trial = 0; trial < 100000; ++trial) {
    double lo = end(rng), hi = end(rng);
    if (lo > hi) std::swap(lo, hi);
    const UpwardInterval r = reciprocal(UpwardInterval{-lo, hi});
    const Interval br = Interval(1.0) / Interval(lo, hi);
    ASSERT_EQ(-r.neg_lo, br.lower()) << trial;
    ASSERT_EQ(r.hi, br.upper()) << trial;
  }
  // An interval holding zero has no bounded reciprocal: the whole line, not a wrong one.
  const UpwardInterval whole = reciprocal(UpwardInterval{1.0, 1.0});
  EXPECT_TRUE(std::isinf(whole.neg_lo) && std::isinf(whole.hi));
}

// Two intervals side by side (UpwardPair, the zone bound's over-the-box and at-the-centre lanes) give
// each lane the single interval's ends to the bit, for every operation and for a whole norm jet.
bool same(const UpwardInterval& a, const UpwardInterval& b) {
  return std::bit_cast<std::uint64_t>(a.neg_lo) == std::bit_cast<std::uint64_t>(b.neg_lo) &&
         std::bit_cast<std::uint64_t>(a.hi) == std::bit_cast<std::uint64_t>(b.hi);
}

TEST(UpwardJet, PairsAreTheSingleIntervalsLaneByLane) {
  const RoundingScope rounding;
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> coefficient(-4.0, 4.0);
  for (int trial = 0; trial < 100000; ++trial) {
    const UpwardInterval a = random_interval(rng), b = random_interval(rng), c = random_interval(rng),
                         d = random_interval(rng);
    const UpwardPair ac = pair_of(a, c), bd = pair_of(b, d);
    const double k = coefficient(rng);
    const UpwardPair results[] = {ac * bd, ac + bd, ac - bd, square(ac), reciprocal(ac), scaled(k, ac), -ac};
    const UpwardInterval first[] = {a * b, a + b, a - b, square(a), reciprocal(a), scaled(k, a), -a};
    const UpwardInterval second[] = {c * d, c + d, c - d, square(c), reciprocal(c), scaled(k, c), -c};
    for (int op = 0; op < 7; ++op) {
      ASSERT_TRUE(same(lane_of(results[op], 0), first[op])) << trial << " op " << op;
      ASSERT_TRUE(same(lane_of(results[op], 1), second[op])) << trial << " op " << op;
    }
  }
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 2000; ++trial) {
    Eigen::Matrix<double, Eigen::Dynamic, 9> C(3 + trial % 7, 9);
    for (int i = 0; i < C.rows(); ++i)
      for (int j = 0; j < 9; ++j) C(i, j) = trial % 3 == 0 && j % 4 == 1 ? 0.0 : g(rng);
    std::array<UpwardJet, 3> x0, x1;
    std::array<UpwardJetT<__m128d>, 3> x;
    for (int i = 0; i < 3; ++i) {
      UpwardInterval parts0[6], parts1[6];
      for (int p = 0; p < 6; ++p) {
        parts0[p] = random_interval(rng);
        parts1[p] = random_interval(rng);
      }
      x0[i] = {parts0[0], parts0[1], parts0[2], parts0[3], parts0[4], parts0[5]};
      x1[i] = {parts1[0], parts1[1], parts1[2], parts1[3], parts1[4], parts1[5]};
      x[i] = {pair_of(parts0[0], parts1[0]), pair_of(parts0[1], parts1[1]), pair_of(parts0[2], parts1[2]),
              pair_of(parts0[3], parts1[3]), pair_of(parts0[4], parts1[4]), pair_of(parts0[5], parts1[5])};
    }
    const UpwardJetT<__m128d> both = norm2_jet(C, x);
    const UpwardJet f0 = norm2_jet(C, x0), f1 = norm2_jet(C, x1);
    const UpwardJet l0 = lane_of(both, 0), l1 = lane_of(both, 1);
    const UpwardInterval UpwardJet::*parts[] = {&UpwardJet::v,  &UpwardJet::du, &UpwardJet::dt,
                                                &UpwardJet::uu, &UpwardJet::ut, &UpwardJet::tt};
    for (auto part : parts) {
      ASSERT_TRUE(same(l0.*part, f0.*part)) << trial;
      ASSERT_TRUE(same(l1.*part, f1.*part)) << trial;
    }
  }
}

// |C h(x)|^2 on point jets is the value at x: the enclosure holds the value computed in long double
// (whose error, a few units of 2^-64, is far below the double enclosure's width).
TEST(UpwardJet, NormOnAPointEnclosesItsValue) {
  const RoundingScope rounding;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 2000; ++trial) {
    Eigen::Matrix<double, Eigen::Dynamic, 9> C(9, 9);
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) C(i, j) = g(rng);
    double x[3] = {g(rng), g(rng), g(rng)};
    const std::array<UpwardJet, 3> jets{constant(point(x[0])), constant(point(x[1])), constant(point(x[2]))};
    const UpwardJet f = norm2_jet(C, jets);
    const long double X = x[0], Y = x[1], Z = x[2];
    const long double h[9] = {X, Y, Z, X * X, Y * Y, Z * Z, X * Y, Y * Z, Z * X};
    long double v = 0;
    for (int i = 0; i < 9; ++i) {
      long double y = 0;
      for (int k = 0; k < 9; ++k) y += static_cast<long double>(C(i, k)) * h[k];
      v += y * y;
    }
    const long double slack = 1e-17L * v;
    EXPECT_LE(static_cast<long double>(-f.v.neg_lo), v + slack) << trial;
    EXPECT_GE(static_cast<long double>(f.v.hi), v - slack) << trial;
    EXPECT_LE(f.v.hi + f.v.neg_lo, 1e-12 * std::abs(f.v.hi)) << trial;  // a point's enclosure is narrow
    EXPECT_EQ(f.du.hi, 0.0);
  }
}

}  // namespace
}  // namespace scalcal
