// Known answers derived by hand from the moments of octahedrally symmetric programs.
// For a program invariant under the 48 signed permutations of the axes, odd moments vanish,
// E[x^2] = 1/3, E[x^4] = a, E[x^2 y^2] = b, and H^T H / N = diag(I/3, Q, b I) with
// Q = (a - b) I + b J. Hence (with eigenvalues 1/3 (x4), a - b (x2), b (x3)):
//   N^9 det K = 81 / ((a - b)^2 b^3),  N trace K = 12 + 2/(a - b) + 3/b,
//   N lambda_max K = 1 / min(1/3, a - b, b),  diag(N K) = 3, (1 - 3b)/(a - b), 1/b.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "numeric/criteria/evaluation.hpp"

namespace scalcal {
namespace {

struct HandMoments {
  double a, b;
  Mat9 information_over_n() const {
    Mat9 m = Mat9::Zero();
    m.topLeftCorner<3, 3>() = Mat3::Identity() / 3.0;
    m.block<3, 3>(3, 3) = (a - b) * Mat3::Identity() + b * Mat3::Ones();
    m.bottomRightCorner<3, 3>() = b * Mat3::Identity();
    return m;
  }
  double D() const { return 81.0 / ((a - b) * (a - b) * b * b * b); }
  double A() const { return 12.0 + 2.0 / (a - b) + 3.0 / b; }
  double E() const { return 1.0 / std::min({1.0 / 3.0, a - b, b}); }
  double S() const { return std::max({3.0, (1.0 - 3.0 * b) / (a - b), 1.0 / b}); }
};

void expect_matches(const Program& p, const HandMoments& hand) {
  const Evaluation ev = evaluate(p);
  ASSERT_EQ(ev.rank, 9);
  const Mat9 expected = hand.information_over_n() * p.size();
  EXPECT_LT((ev.information - expected).cwiseAbs().maxCoeff(), 1e-12 * p.size());
  EXPECT_NEAR(ev.value(CriterionKind::D) / hand.D(), 1.0, 1e-12);
  EXPECT_NEAR(ev.value(CriterionKind::A) / hand.A(), 1.0, 1e-12);
  EXPECT_NEAR(ev.value(CriterionKind::E) / hand.E(), 1.0, 1e-12);
  EXPECT_NEAR(ev.value(CriterionKind::S) / hand.S(), 1.0, 1e-12);
}

// Axes (6): x^4 = 1 on 2 of 6. Edges (12): x^4 = 1/4 on 8 of 12, x^2 y^2 = 1/4 on 4 of 12.
// Together (18): sum x^4 = 2 + 2 = 4, sum x^2 y^2 = 1, so a = 2/9, b = 1/18.
TEST(HandMoments, Classic18) {
  expect_matches(Program::classic18(), {2.0 / 9.0, 1.0 / 18.0});
  const Evaluation ev = evaluate(Program::classic18());
  // 81 / ((1/6)^2 (1/18)^3) = 81 * 36 * 5832, exactly.
  EXPECT_NEAR(ev.value(CriterionKind::D) / 17006112.0, 1.0, 1e-14);
  EXPECT_NEAR(ev.theta_bias, std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(ev.theta_scale, std::sqrt(5.0), 1e-14);
  EXPECT_NEAR(ev.theta_nonorth, std::sqrt(18.0), 1e-14);
}

// The 12 edge positions alone: a = 1/6, b = 1/12.
TEST(HandMoments, Edges12) { expect_matches(Program::octahedral(0, 1, 0), {1.0 / 6.0, 1.0 / 12.0}); }

// Axes + diagonals (14): sum x^4 = 2 + 8/9, sum x^2 y^2 = 8/9.
TEST(HandMoments, AxesAndDiagonals14) {
  expect_matches(Program::octahedral(1, 0, 1), {(2.0 + 8.0 / 9.0) / 14.0, (8.0 / 9.0) / 14.0});
}

// Three uniform great circles (k >= 5 points per ring integrate degree-4 trigonometric
// polynomials exactly): on a circle E[c^4] = 3/8, E[c^2 s^2] = 1/8; x lies in two of the three
// rings, the pair (x, y) in one, so a = (2/3)(3/8) = 1/4 and b = (1/3)(1/8) = 1/24.
TEST(HandMoments, RotationProgramsFromFiveOn) {
  for (int k = 5; k <= 12; ++k) {
    SCOPED_TRACE(k);
    expect_matches(Program::rotation(k), {0.25, 1.0 / 24.0});
    expect_matches(Program::rotation(k, 17.0), {0.25, 1.0 / 24.0});
  }
}

// The jigs are spherical 5-designs, so their moments are the sphere's: a = 1/5, b = 1/15, and
// N^9 det K = 81 / ((2/15)^2 (1/15)^3) = 61509375/4.
TEST(HandMoments, DodecahedralAndIcosahedralJigs) {
  expect_matches(Program::dodecahedral(), {0.2, 1.0 / 15.0});
  expect_matches(Program::icosahedral(), {0.2, 1.0 / 15.0});
  EXPECT_NEAR(evaluate(Program::icosahedral()).value(CriterionKind::D), 61509375.0 / 4.0, 1e-6);
}

}  // namespace
}  // namespace scalcal
