// The subcommands' JSON keys, as issue 3 names them, and exit status 2 on bad options.
#include <gtest/gtest.h>

#include <string>

#include "tests/common/run_cli.hpp"

namespace {

std::pair<int, std::string> run(const std::string& args) {
  const auto r = scalcal::testing::run_cli(args);
  return {r.status, r.out};
}

TEST(OptimizeCli, JsonKeys) {
  const auto [code, out] = run("optimize --positions 9 --criterion D --starts 2 --digits 30 --json");
  ASSERT_EQ(code, 0);
  for (const char* key : {"\"criterion\"", "\"positions\"", "\"value\"", "\"program\"", "\"starts\"", "\"hits\"",
                          "\"seconds\"", "\"value_digits\"", "\"residual\"", "\"distinct\"", "\"local_solver\"",
                          "\"confirmed\""})
    EXPECT_NE(out.find(key), std::string::npos) << key;
}

TEST(RandomCli, JsonKeys) {
  const auto [code, out] = run("random --positions 12 --count 1000 --json");
  ASSERT_EQ(code, 0);
  for (const char* key : {"\"best\"", "\"count\"", "\"program\"", "\"seconds\""})
    EXPECT_NE(out.find(key), std::string::npos) << key;
}

TEST(SynthesisCli, BadOptionsExitTwo) {
  EXPECT_EQ(run("optimize --positions 18 --criterion Q").first, 2);
  EXPECT_EQ(run("optimize --positions 8").first, 2);
  EXPECT_EQ(run("optimize --criterion D").first, 2);
  EXPECT_EQ(run("optimize --positions 12 --local fast").first, 2);
  EXPECT_EQ(run("random --positions 18").first, 2);
  EXPECT_EQ(run("sweep --positions 12..10").first, 2);
  EXPECT_EQ(run("sweep --criteria D,X").first, 2);
}

}  // namespace
