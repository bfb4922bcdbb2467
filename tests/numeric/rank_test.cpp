// Rank-deficient programs are reported with their rank and the parameters they cannot identify,
// worked out by hand from which columns of H vanish or coincide.
#include <gtest/gtest.h>

#include <cmath>

#include "numeric/criteria/evaluation.hpp"

namespace scalcal {
namespace {

std::vector<std::string_view> names(const Evaluation& ev) {
  std::vector<std::string_view> out;
  for (int r : ev.unidentifiable) out.push_back(kParameterNames[r]);
  return out;
}

// All positions in the x-y plane: the columns z, z^2, yz, zx of H vanish; x, y, x^2, y^2, xy
// stay independent (there is no constant column for x^2 + y^2 = 1 to collide with): rank 5.
TEST(Rank, PlanarProgram) {
  Program p;
  for (int j = 0; j < 12; ++j) p.positions.emplace_back(std::cos(0.5 * j), std::sin(0.5 * j), 0.0);
  const Evaluation ev = evaluate(p);
  EXPECT_EQ(ev.rank, 5);
  EXPECT_EQ(names(ev), (std::vector<std::string_view>{"bias_z", "scale_z", "nonorth_yz", "nonorth_zx"}));
  EXPECT_TRUE(std::isinf(ev.value(CriterionKind::D)));
}

// rotation-4 with phase 0 visits only the six axis positions (twice each): products vanish, and
// the axis rows span the six linear and square columns: rank 6, no non-orthogonality.
TEST(Rank, RotationFourOnlyVisitsTheAxes) {
  const Evaluation ev = evaluate(Program::rotation(4));
  EXPECT_EQ(ev.rank, 6);
  EXPECT_EQ(names(ev), (std::vector<std::string_view>{"nonorth_xy", "nonorth_yz", "nonorth_zx"}));
}

// The 8 diagonal positions repeated: x^2 = y^2 = z^2 = 1/3 everywhere, so the three scale columns
// are equal (rank drops by 2); linear and product columns are independent: rank 7.
TEST(Rank, DiagonalsOnly) {
  const Evaluation ev = evaluate(Program::octahedral(0, 0, 2));
  EXPECT_EQ(ev.rank, 7);
  EXPECT_EQ(names(ev), (std::vector<std::string_view>{"scale_x", "scale_y", "scale_z"}));
}

TEST(Rank, FullRankProgramHasNoUnidentifiableParameter) {
  const Evaluation ev = evaluate(Program::classic18());
  EXPECT_EQ(ev.rank, 9);
  EXPECT_TRUE(ev.unidentifiable.empty());
  EXPECT_NEAR(ev.condition, 6.0, 1e-12);  // eigenvalues 18 * {1/3, 1/6, 1/18}: 6 = (1/3)/(1/18)
}

}  // namespace
}  // namespace scalcal

namespace scalcal {
namespace {

// Nearly planar (z = +-1e-5): the z^2 column of H is ~1e-10, so H^T H has condition ~1e20, beyond
// what an eigen-decomposition of H^T H resolves in double (it can return a negative eigenvalue and
// hence a negative E). The SVD of H keeps every criterion positive and of the right size.
TEST(Rank, NearlySingularProgramKeepsPositiveCriteria) {
  Program p;
  for (int j = 0; j < 12; ++j)
    p.positions.push_back(
        Vec3(std::cos(0.5 * j), std::sin(0.5 * j), (j % 2 ? 1e-5 : -1e-5) * (1 + j % 3)).normalized());
  const Evaluation ev = evaluate(p);
  ASSERT_EQ(ev.rank, 9);
  EXPECT_GT(ev.value(CriterionKind::E), 1e15);
  EXPECT_GT(ev.value(CriterionKind::D), 0.0);
  EXPECT_GT(ev.condition, 1e15);
  EXPECT_GE(ev.value(CriterionKind::S), ev.value(CriterionKind::E) / 9.0);  // max diagonal >= trace/9 >= lambda_max/9
}

}  // namespace
}  // namespace scalcal
