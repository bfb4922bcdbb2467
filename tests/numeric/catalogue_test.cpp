// The catalogue: names resolve, sizes are those of the paper's programs, and the tables are read
// with the paper's angle convention.
#include <gtest/gtest.h>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/catalogue.hpp"

namespace scalcal {
namespace {

TEST(Catalogue, SizesOfNamedPrograms) {
  EXPECT_EQ(named_program("classic18")->size(), 18);
  EXPECT_EQ(named_program("rotation-6")->size(), 18);
  EXPECT_EQ(named_program("rotation-7-p12.5")->size(), 21);
  EXPECT_EQ(named_program("nine-2axes")->size(), 9);
  EXPECT_EQ(named_program("nine-3axes")->size(), 9);
  EXPECT_EQ(named_program("octahedral-1-1-1")->size(), 26);
  EXPECT_EQ(named_program("dodecahedral-12")->size(), 12);
  EXPECT_EQ(named_program("icosahedral-20")->size(), 20);
  EXPECT_EQ(named_program("random-31-s9")->size(), 31);
  for (const char* t : {"table1-A", "table2-E", "table3-S"}) EXPECT_EQ(named_program(t)->size(), 18);
  EXPECT_FALSE(named_program("no-such-program").has_value());
}

TEST(Catalogue, EveryPositionIsAUnitVector) {
  for (const auto& e : catalogue())
    for (const auto& eta : e.program.positions) EXPECT_NEAR(eta.norm(), 1.0, 1e-14) << e.name;
}

TEST(Catalogue, Rotation6IsFig2) {
  // Fig. 2: six positions 60 degrees apart while turning about each axis; each axis appears
  // once along and once against the vector.
  const Program p = *named_program("rotation-6");
  int along_axes = 0;
  for (const auto& e : p.positions)
    if (e.cwiseAbs().maxCoeff() > 1 - 1e-12) ++along_axes;
  EXPECT_EQ(along_axes, 6);
}

TEST(Catalogue, TableOneFirstPosition) {
  // Position 1 of Table 1: alpha1 = -151.1, alpha2 = -69.8 degrees.
  const Program p = *named_program("table1-A");
  const double a1 = -151.1 * M_PI / 180, a2 = -69.8 * M_PI / 180;
  EXPECT_NEAR(p.positions[0](0), std::cos(a2) * std::cos(a1), 1e-15);
  EXPECT_NEAR(p.positions[0](2), std::sin(a2), 1e-15);
}

TEST(Catalogue, RandomProgramsAreReproducible) {
  const Program a = Program::random(15, 42), b = Program::random(15, 42), c = Program::random(15, 43);
  for (int i = 0; i < 15; ++i) EXPECT_EQ(a.positions[i], b.positions[i]);
  EXPECT_NE(a.positions[0], c.positions[0]);
}

TEST(Catalogue, UnknownNameIsAnInputError) {
  EXPECT_THROW(resolve_program("no-such-program"), InputError);
  EXPECT_THROW(resolve_program("rotation-2"), InputError);
}

}  // namespace
}  // namespace scalcal
