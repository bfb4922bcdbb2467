// Invariants: a rotation of the program leaves D unchanged (h transforms by a matrix of
// determinant +-1); a signed permutation of the axes leaves every criterion unchanged (it acts on
// h as a signed permutation, an orthogonal map).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include <Eigen/Geometry>

#include "numeric/criteria/evaluation.hpp"

namespace scalcal {
namespace {

Program transformed(const Program& p, const Mat3& R) {
  Program q;
  for (const auto& e : p.positions) q.positions.push_back(R * e);
  return q;
}

TEST(Invariance, RotationLeavesDUnchanged) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const Program p = Program::random(9 + static_cast<int>(seed), seed);
    SphereSampler s(1000 + seed);
    const Vec3 axis = s();
    const double angle = 2 * M_PI * s.uniform();
    const Mat3 R = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    const Evaluation a = evaluate(p), b = evaluate(transformed(p, R));
    EXPECT_NEAR(b.value(CriterionKind::D) / a.value(CriterionKind::D), 1.0, 1e-9) << "seed " << seed;
  }
}

TEST(Invariance, RotationChangesTheOtherCriteria) {
  // A guard that the invariance test above is not vacuous: A moves under a generic rotation.
  const Program p = Program::classic18();
  const Mat3 R = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  EXPECT_GT(std::abs(evaluate(transformed(p, R)).value(CriterionKind::A) - evaluate(p).value(CriterionKind::A)), 1e-3);
}

TEST(Invariance, SignedPermutationsLeaveEveryCriterionUnchanged) {
  const Program p = Program::random(17, 7);
  const Evaluation base = evaluate(p);
  std::array<int, 3> perm = {0, 1, 2};
  do {
    for (int signs = 0; signs < 8; ++signs) {
      Mat3 P = Mat3::Zero();
      for (int i = 0; i < 3; ++i) P(i, perm[i]) = (signs >> i & 1) ? -1.0 : 1.0;
      const Evaluation ev = evaluate(transformed(p, P));
      EXPECT_NEAR(ev.value(CriterionKind::D) / base.value(CriterionKind::D), 1.0, 1e-10);
      EXPECT_NEAR(ev.value(CriterionKind::A) / base.value(CriterionKind::A), 1.0, 1e-10);
      EXPECT_NEAR(ev.value(CriterionKind::E) / base.value(CriterionKind::E), 1.0, 1e-10);
      EXPECT_NEAR(ev.value(CriterionKind::S) / base.value(CriterionKind::S), 1.0, 1e-10);
      EXPECT_NEAR(ev.theta_nonorth / base.theta_nonorth, 1.0, 1e-10);
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
}

TEST(Invariance, OrderOfPositionsDoesNotMatter) {
  Program p = Program::random(12, 3);
  const Evaluation a = evaluate(p);
  std::reverse(p.positions.begin(), p.positions.end());
  EXPECT_NEAR(evaluate(p).value(CriterionKind::A) / a.value(CriterionKind::A), 1.0, 1e-12);
}

}  // namespace
}  // namespace scalcal
