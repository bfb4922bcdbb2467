// The subcommands' JSON keys, as issue 3 names them, exit status 2 on bad options, and the
// polished program as what `optimize --digits --out` writes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/common/run_cli.hpp"

namespace {

std::pair<int, std::string> run(const std::string& args) {
  const auto r = scalcal::testing::run_cli(args);
  return {r.status, r.out};
}

TEST(OptimizeCli, JsonKeys) {
  const auto [code, out] = run("optimize --positions 9 --criterion D --starts 2 --digits 30 --json");
  ASSERT_EQ(code, 0);
  for (const char* key :
       {"\"criterion\"", "\"positions\"", "\"value\"", "\"program\"", "\"starts\"", "\"stopping\"", "\"hits\"",
        "\"seconds\"", "\"value_digits\"", "\"residual\"", "\"distinct\"", "\"local_solver\"", "\"confirmed\""})
    EXPECT_NE(out.find(key), std::string::npos) << key;
}

// S at N = 12 reaches its limit 6 + 3 sqrt 3 (proofs/; README). Ipopt stops about 1e-11 above it;
// the polished program, rounded to double, is within rounding of it: that is the one written.
TEST(OptimizeCli, DigitsWritesThePolishedProgram) {
  const auto file = (scalcal::testing::scratch_dir() / "s12.csv").string();
  const auto r = scalcal::testing::run_cli("optimize --positions 12 --criterion S --starts 2 --digits 30 --out " +
                                           file + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("converged"), true);
  EXPECT_TRUE(j.contains("iterations"));
  const double limit = 6 + 3 * std::sqrt(3.0);
  EXPECT_EQ(j.at("value_digits").get<std::string>().substr(0, 14), "11.19615242270");
  const auto e = scalcal::testing::run_cli("evaluate " + file + " --json");
  ASSERT_EQ(e.status, 0) << e.err;
  EXPECT_NEAR(nlohmann::json::parse(e.out).at("S").get<double>(), limit, 2e-14 * limit);
  // The JSON program is the same polished program as the file.
  const auto program = j.at("program");
  std::string csv = scalcal::testing::slurp(file);
  ASSERT_EQ(program.size(), 12u);
  const auto first_row = csv.substr(csv.find('\n') + 1);
  EXPECT_EQ(std::stod(first_row.substr(0, first_row.find(','))), program[0][0].get<double>());
}

// With --digits, `value` is the polished program's, the one printed and written, as evaluate finds it to rounding
// (the file's reader normalises each position again): E at N = 12, whose limit 12 the 12 edge positions attain
// (proofs/aes_limits.md), ends the multistart 1.6e-11 above it, the polished program within 1e-14.
TEST(OptimizeCli, DigitsValueIsThePolishedPrograms) {
  const auto file = (scalcal::testing::scratch_dir() / "e12.csv").string();
  const auto r = scalcal::testing::run_cli("optimize --positions 12 --criterion E --starts 4 --digits 30 --out " +
                                           file + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto e = scalcal::testing::run_cli("evaluate " + file + " --json");
  ASSERT_EQ(e.status, 0) << e.err;
  const double evaluated = nlohmann::json::parse(e.out).at("E").get<double>();
  EXPECT_NEAR(evaluated, 12.0, 1e-13);
  EXPECT_NEAR(j.at("value").get<double>(), evaluated, 1e-13);
}

// Without a polish, S at N = 18 ends within 1e-14 of 6 + 3 sqrt 3 (Newton on the active conditions
// after Ipopt), and the default multistart says why it stopped.
TEST(OptimizeCli, SReachesItsLimitToRounding) {
  const auto r = scalcal::testing::run_cli("optimize --positions 18 --criterion S --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double limit = 6 + 3 * std::sqrt(3.0);
  EXPECT_NEAR(j.at("value").get<double>(), limit, 1e-14 * limit);
  EXPECT_EQ(j.at("stopping").get<std::string>(), "8 consecutive hits");
  EXPECT_EQ(j.at("starts").get<int>(), 8);
}

TEST(OptimizeCli, UnwritableOutIsAnError) {
  const auto r = scalcal::testing::run_cli("optimize --positions 9 --starts 1 --out /dev/full");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << r.err;
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
