// Decimals in family parameters stand for exact fractions (symbolic/exact.hpp: exact_decimals): the
// fuzzer's input `orientation=q:1,5,0,1.` once gave a GiNaC division by zero or, other times, printed
// forms that changed from run to run, since GiNaC kept 1. as a float.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"

namespace sym = scalcal::symbolic;
using GiNaC::ex;

namespace {

TEST(ExactDecimals, DecimalsBecomeTheFractionsTheyName) {
  GiNaC::parser reader;
  // Expected values by hand: 0.1 = 1/10, 2.5e-3 = 1/400, 1. = 1, -0.75 = -3/4.
  EXPECT_TRUE(sym::exact_decimals(reader("0.1")).is_equal(GiNaC::numeric(1, 10)));
  EXPECT_TRUE(sym::exact_decimals(reader("2.5e-3")).is_equal(GiNaC::numeric(1, 400)));
  EXPECT_TRUE(sym::exact_decimals(reader("1.")).is_equal(ex(1)));
  EXPECT_TRUE(sym::exact_decimals(reader("-0.75")).is_equal(GiNaC::numeric(-3, 4)));
  // Inside an expression and beside a symbol; exact numbers and symbols are left alone.
  const ex e = sym::exact_decimals(reader("0.5*x+sqrt(2)"));
  EXPECT_TRUE((e - reader("x/2+sqrt(2)")).expand().is_zero()) << e;
  EXPECT_TRUE(GiNaC::is_a<GiNaC::numeric>(sym::exact_decimals(reader("3/7"))));
  EXPECT_TRUE(sym::exact_decimals(reader("3/7")).is_equal(GiNaC::numeric(3, 7)));
}

TEST(ExactDecimals, ADecimalQuaternionGivesTheExactJig) {
  const auto& f = sym::find_family("jig:icosahedron");
  const auto exact = f.instance(sym::parse_params(f, {"orientation=q:1,5,0,1"}));
  std::string first;
  for (int run = 0; run < 3; ++run) {
    const auto decimal = f.instance(sym::parse_params(f, {"orientation=q:1,5,0,1."}));
    ASSERT_EQ(decimal.M.rows(), 9u);
    for (unsigned r = 0; r < 9; ++r)
      for (unsigned c = 0; c < 9; ++c)
        EXPECT_TRUE(sym::is_zero_exact(decimal.M(r, c) - exact.M(r, c))) << r << "," << c;
    std::string text;
    for (unsigned r = 0; r < 9; ++r)
      for (unsigned c = 0; c < 9; ++c) text += sym::canonical_text(decimal.M(r, c)) + ";";
    if (run == 0) first = text;
    EXPECT_EQ(text, first);  // the same bytes every time
  }
}

}  // namespace
