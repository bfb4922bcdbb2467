// Units of a calibration (numeric/calibration/units.hpp): names, factors and the Earth's magnitudes,
// against values written down by hand (standard gravity 9.80665 m/s^2, 1 gauss = 100 uT = 1e5 nT).
#include <cmath>

#include <gtest/gtest.h>

#include "numeric/calibration/units.hpp"

namespace scalcal {
namespace {

TEST(Units, NamesAndFactors) {
  EXPECT_DOUBLE_EQ(factor(*parse_unit("g"), *parse_unit("m/s^2")), 9.80665);
  EXPECT_DOUBLE_EQ(factor(*parse_unit("mg"), *parse_unit("m/s/s")), 9.80665e-3);
  EXPECT_DOUBLE_EQ(factor(*parse_unit("uT"), *parse_unit("mG")), 10);
  EXPECT_DOUBLE_EQ(factor(*parse_unit("\xC2\xB5T"), *parse_unit("gauss")), 0.01);
  EXPECT_DOUBLE_EQ(factor(*parse_unit("nT"), *parse_unit("uT")), 1e-3);
  EXPECT_DOUBLE_EQ(factor(*parse_unit("dps"), *parse_unit("rad/s")), M_PI / 180);
  // milli-g and milligauss are told apart by case; a bare "G" is neither.
  EXPECT_EQ(parse_unit("mg")->quantity, Quantity::acceleration);
  EXPECT_EQ(parse_unit("mG")->quantity, Quantity::magnetic_field);
  EXPECT_FALSE(parse_unit("G"));
  EXPECT_FALSE(parse_unit("counts"));
  EXPECT_TRUE(is_count_unit("counts"));
  EXPECT_TRUE(is_count_unit("LSB"));
}

TEST(Units, TheEarthFixesSomeMagnitudes) {
  EXPECT_EQ(unit_of_earth_magnitude(Instrument::accel, 9.81744)->name, "m/s^2");
  EXPECT_EQ(unit_of_earth_magnitude(Instrument::accel, 1)->name, "g");
  EXPECT_EQ(unit_of_earth_magnitude(Instrument::accel, 1000)->name, "mg");
  EXPECT_EQ(unit_of_earth_magnitude(Instrument::mag, 48.3)->name, "uT");
  EXPECT_EQ(unit_of_earth_magnitude(Instrument::mag, 0.483)->name, "gauss");
  EXPECT_EQ(unit_of_earth_magnitude(Instrument::mag, 483)->name, "mG");
  EXPECT_EQ(unit_of_earth_magnitude(Instrument::mag, 48300)->name, "nT");
  EXPECT_FALSE(unit_of_earth_magnitude(Instrument::accel, 4096));  // counts per g: no unit
  EXPECT_FALSE(unit_of_earth_magnitude(Instrument::mag, 9.80665));
  EXPECT_FALSE(unit_of_earth_magnitude(Instrument::gyro, 1));
}

TEST(Units, AnAmountIsANumberWithItsUnit) {
  const auto a = parse_amount("0.061mg");
  ASSERT_TRUE(a);
  EXPECT_DOUBLE_EQ(a->value, 0.061);
  EXPECT_EQ(a->unit.name, "mg");
  const auto b = parse_amount("1/16384 g");
  ASSERT_TRUE(b);
  EXPECT_DOUBLE_EQ(b->value, 1.0 / 16384);
  for (const char* bad : {"", "mg", "0.061", "-1mg", "0mg", "1e400mg", "1/0 g", "0.061 furlongs"})
    EXPECT_FALSE(parse_amount(bad)) << bad;
}

}  // namespace
}  // namespace scalcal
