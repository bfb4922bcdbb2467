// `scalcal family` and `scalcal limits` through the real binary: documented JSON keys, numbers
// that agree with hand-derived values, exit 2 on bad input.
#include <gtest/gtest.h>

#include <string>

#include "tests/common/run_cli.hpp"

namespace {

using Run = scalcal::testing::CliResult;

Run run(const std::string& args) { return scalcal::testing::run_cli(args); }

TEST(FamilyCli, JsonKeys) {
  const auto r = run("family icosahedral --json");
  ASSERT_EQ(r.status, 0);
  for (const char* key :
       {"\"family\": \"icosahedral\"", "\"positions\": \"20\"", "\"positions_value\": 20,", "\"D\": 15377343.75",
        "\"A\": 72", "\"E\": 15", "\"S\": 15", "\"exact\"", "\"D\": \"61509375/4\""})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << "\n" << r.out;
}

TEST(FamilyCli, SymbolicParameters) {
  const auto r = run("family octahedral --param axes=a --param edges=e --param diagonals=d --json");
  ASSERT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("\"D\": null"), std::string::npos) << r.out;
  // positions is always the exact text, here N = 6a + 12e + 8d; positions_value is null.
  EXPECT_NE(r.out.find("\"positions\": \""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\"positions_value\": null"), std::string::npos) << r.out;
  for (const char* term : {"6*a", "12*e", "8*d"}) EXPECT_NE(r.out.find(term), std::string::npos) << term;
}

TEST(FamilyCli, BadInputExits2) {
  EXPECT_EQ(run("family cuboctahedral").status, 2);
  EXPECT_EQ(run("family rotation --param k=2").status, 2);
  EXPECT_EQ(run("family rotation --param q=2").status, 2);
  EXPECT_EQ(run("family octahedral --param edges=0").status, 2);
  EXPECT_EQ(run("family").status, 2);
  EXPECT_EQ(run("limits extra").status, 2);
}

TEST(LimitsCli, JsonKeys) {
  const auto r = run("limits --json");
  ASSERT_EQ(r.status, 0);
  for (const char* key : {"\"D\": {", "\"exact\": \"61509375/4\"", "\"value\": 15377343.75", "\"A\": {",
                          "\"exact\": \"45+18*sqrt(2)\"", "\"E\": {", "\"exact\": \"12\"", "\"S\": {",
                          "\"exact\": \"6+3*sqrt(3)\"", "\"moments\"", "\"E[x^2 y^2]\": \"1/15\""})
    EXPECT_NE(r.out.find(key), std::string::npos) << key;
}

}  // namespace
