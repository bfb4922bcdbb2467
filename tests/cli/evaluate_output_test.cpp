// `scalcal evaluate --json` carries the program and K, `--out` writes any program as CSV, numbers
// print in their shortest round-trip form, and an output that cannot be written is an error.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/common/number_text.hpp"
#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using nlohmann::json;

// classic18 by hand (axes +-e_i, edges (+-1, +-1, 0)/sqrt2 cyclic): H^T H is block diagonal with
// the bias block 6 I (sum x^2 = 2 + 2 + 2), the scale block 3 I + J (sum x^4 = 2 + 8/4, sum x^2 y^2
// = 4/4) and the non-orthogonality block I; so K = diag(I/6, (I - J/6)/3, I).
double classic18_K(int r, int c) {
  if (r < 3) return r == c ? 1.0 / 6 : 0.0;
  if (r < 6) return c < 3 || c >= 6 ? 0.0 : (r == c ? 5.0 / 18 : -1.0 / 18);
  return r == c ? 1.0 : 0.0;
}

TEST(EvaluateOutput, JsonHasTheProgramAndK) {
  const auto r = run_cli("evaluate classic18 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(r.out);
  ASSERT_EQ(j.at("K").size(), 9u);
  for (int a = 0; a < 9; ++a) {
    ASSERT_EQ(j["K"][a].size(), 9u);
    for (int b = 0; b < 9; ++b) EXPECT_NEAR(j["K"][a][b].get<double>(), classic18_K(a, b), 1e-13) << a << "," << b;
  }
  ASSERT_EQ(j.at("program").size(), 18u);
  int axes = 0;
  for (const auto& p : j["program"]) {
    ASSERT_EQ(p.size(), 3u);
    const double x = p[0], y = p[1], z = p[2];
    EXPECT_NEAR(x * x + y * y + z * z, 1.0, 1e-15);
    if (std::abs(std::abs(x) + std::abs(y) + std::abs(z) - 1) < 1e-15) ++axes;
  }
  EXPECT_EQ(axes, 6);
  // The keys documented before stay, in their order, before the new ones.
  std::vector<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.push_back(k);
  EXPECT_EQ(keys.front(), "positions");
  EXPECT_EQ(keys[keys.size() - 2], "program");
  EXPECT_EQ(keys.back(), "K");
}

TEST(EvaluateOutput, JsonNumbersAreShortest) {
  for (const char* program : {"classic18", "table1-A", "icosahedral-20"}) {
    const auto r = run_cli(std::string("evaluate ") + program + " --json");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(overlong_numbers(r.out), std::vector<std::string>{}) << program;
  }
}

TEST(EvaluateOutput, OutWritesAnyProgramAsCsv) {
  const auto file = (scratch_dir() / "nine.csv").string();
  auto r = run_cli("evaluate nine-2axes --out " + file);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string csv = slurp(file);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "x,y,z,alpha1_deg,alpha2_deg");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 10);
  // Read back, the file is the same program: nine-2axes has N^9 det K = 3^18 (numeric/program.hpp).
  r = run_cli("evaluate " + file + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(json::parse(r.out).at("D").get<double>(), std::pow(3.0, 18), std::pow(3.0, 18) * 1e-13);
}

TEST(EvaluateOutput, JsonAsTheValueOfOutIsAFileName) {
  const auto dir = scratch_dir() / "value_json";
  std::filesystem::create_directories(dir);
  const auto r = run_cli("evaluate classic18 --out --json", {dir.string(), ""});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("program classic18: N = 18", 0), 0u) << r.out;  // the table, not JSON
  EXPECT_EQ(slurp((dir / "--json").string()).rfind("x,y,z,alpha1_deg,alpha2_deg\n", 0), 0u);
}

TEST(EvaluateOutput, UnwritableOutputIsAnError) {
  auto r = run_cli("evaluate classic18 --out /dev/full");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << r.err;
  r = run_cli("evaluate classic18 --out /nonexistent/dir/p.csv");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/nonexistent/dir/p.csv"), std::string::npos) << r.err;
  r = run_cli("evaluate classic18 --json", {"", "/dev/full"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("standard output"), std::string::npos) << r.err;
  r = run_cli("catalogue", {"", "/dev/full"});
  EXPECT_EQ(r.status, 1) << r.err;
}

}  // namespace
}  // namespace scalcal::testing
