// augment: the given positions are kept bit for bit, every added one is inside the region, and no
// added position makes the unnormalised criterion (K itself) worse.
#include <cmath>
#include <iomanip>

#include <gtest/gtest.h>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/region/augment.hpp"

namespace scalcal {
namespace {

// The criterion of K without the normalisation by N: det K, trace K, lambda_max K, max K(r,r).
double raw(CriterionKind c, const Program& p) {
  const double v = evaluate(p).value(c);
  const double n = p.size();
  return c == CriterionKind::D ? v / std::pow(n, 9) : v / n;
}

TEST(Augment, KeepsTheGivenPositionsAndNeverMakesKWorse) {
  const Program given = resolve_program("nine-3axes");
  const Region cap = parse_region({"cap:50:1,1,1"});
  for (auto c : kCriteria) {
    const AugmentedProgram a = augment_program(given, 4, c, cap);
    ASSERT_EQ(a.program.size(), given.size() + 4);
    for (int i = 0; i < given.size(); ++i)
      for (int k = 0; k < 3; ++k)  // bit for bit: no renormalisation, no reordering
        EXPECT_EQ(a.program.positions[i](k), given.positions[i](k));
    for (const Vec3& x : a.added) EXPECT_TRUE(cap.contains(x, 1e-9));
    Program prefix = given;
    double before = raw(c, prefix);
    for (const Vec3& x : a.added) {
      prefix.positions.push_back(x);
      const double after = raw(c, prefix);
      EXPECT_LE(after, before * (1 + 1e-12)) << criterion_name(c);
      before = after;
    }
    EXPECT_NEAR(a.value, evaluate(a.program).value(c), 1e-9 * a.value);
  }
}

// rotation-4 is rank 6 (no non-orthogonality information); three added positions off its planes
// make it rank 9, and the greedy step must find them although every candidate's criterion is
// infinite until the last one.
TEST(Augment, RepairsARankDeficientProgram) {
  const Program given = resolve_program("rotation-4");
  ASSERT_EQ(evaluate(given).rank, 6);
  const AugmentedProgram a = augment_program(given, 3, CriterionKind::D, sphere_region());
  EXPECT_FALSE(std::isfinite(a.value_before));
  EXPECT_EQ(evaluate(a.program).rank, 9);
  EXPECT_TRUE(std::isfinite(a.value));
}

// Adding to the D-optimal 12-point jig cannot beat the limit; adding 8 cube diagonals to the 6
// axis positions gives octahedral-1-0-1's value; greedy plus exchange must get that to the settling
// precision (positions moved in steps down to 1e-4 degrees, coupled through K: 1e-6 relative).
TEST(Augment, AxesPlusEightIsAtLeastAsGoodAsTheCubeDiagonals) {
  const Program axes = Program::octahedral(1, 0, 0);
  const AugmentedProgram a = augment_program(axes, 8, CriterionKind::D, sphere_region());
  const double diagonals = evaluate(Program::octahedral(1, 0, 1)).value(CriterionKind::D);
  EXPECT_LE(a.value, diagonals * (1 + 1e-6)) << std::setprecision(17) << a.value << " " << diagonals;
  EXPECT_GE(a.value, criterion_limit(CriterionKind::D).value);
}

}  // namespace
}  // namespace scalcal
