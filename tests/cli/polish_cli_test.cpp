// `scalcal polish PROGRAM --criterion C --digits P`: any program, from the catalogue or a file, is
// polished in MPFR; --out writes the polished program, and its value is a closed form derived by
// hand (the D limit 61509375/4 of a spherical 4-design; classic18's 17006112 = 18^9 / 11664).
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

using nlohmann::json;

// The icosahedral jig (the dodecahedron's vertices: a spherical 4-design, so D = 61509375/4),
// every coordinate moved by up to 1e-3: no longer optimal, but within Newton's reach.
std::string perturbed_icosahedral() {
  const double phi = (1 + std::sqrt(5.0)) / 2;
  std::vector<std::array<double, 3>> p;
  for (int s1 : {1, -1})
    for (int s2 : {1, -1})
      for (int s3 : {1, -1}) p.push_back({double(s1), double(s2), double(s3)});
  for (int c = 0; c < 3; ++c)
    for (int s1 : {1, -1})
      for (int s2 : {1, -1}) {
        std::array<double, 3> v{};
        v[(c + 1) % 3] = s1 / phi;
        v[(c + 2) % 3] = s2 * phi;
        p.push_back(v);
      }
  std::string csv = "x,y,z\n";
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double n = std::sqrt(3.0);
    char row[128];
    std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g\n", p[i][0] / n + 1e-3 * std::sin(i + 1.0),
                  p[i][1] / n + 1e-3 * std::cos(3.0 * i), p[i][2] / n - 7e-4 * std::sin(2.0 * i));
    csv += row;
  }
  return csv;
}

double D_of(const std::string& program) {
  const auto r = run_cli("evaluate " + program + " --json");
  EXPECT_EQ(r.status, 0) << r.err;
  return r.status == 0 ? json::parse(r.out).at("D").get<double>() : NAN;
}

TEST(PolishCli, PolishesAFileAndWritesThePolishedProgram) {
  constexpr double limit = 61509375.0 / 4;
  const auto in = write_file("perturbed20.csv", perturbed_icosahedral());
  const auto out = (scratch_dir() / "polished20.csv").string();
  ASSERT_GT(D_of(in), limit * (1 + 1e-8));  // the start is visibly off the optimum
  const auto r = run_cli("polish " + in + " --criterion D --digits 30 --out " + out + " --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const json j = json::parse(r.out);
  for (const char* key :
       {"criterion", "positions", "value_digits", "residual", "digits", "iterations", "converged", "program"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["criterion"], "D");
  EXPECT_EQ(j["positions"], 20);
  EXPECT_EQ(j["digits"], 30);
  EXPECT_EQ(j["converged"], true);
  EXPECT_GT(j["iterations"].get<int>(), 0);
  EXPECT_LT(j["residual"].get<double>(), 1e-35);
  EXPECT_EQ(j["value_digits"].get<std::string>().substr(0, 31), "15377343.7500000000000000000000");
  ASSERT_EQ(j["program"].size(), 20u);
  // The file is the polished program: at the optimum to double precision.
  EXPECT_NEAR(D_of(out), limit, limit * 1e-13);
}

TEST(PolishCli, PolishesACatalogueProgram) {
  // classic18 is a stationary point of D by its octahedral symmetry: the polish stays there.
  const auto r = run_cli("polish classic18 --criterion D --digits 20");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("D = 17006112.000000000000  (20 digits, residual ", 0), 0u) << r.out;
}

TEST(PolishCli, BadInputExitsTwoAndUnwritableOutputOne) {
  EXPECT_EQ(run_cli("polish no-such-program --criterion D").status, 2);
  EXPECT_EQ(run_cli("polish classic18 --criterion X").status, 2);
  EXPECT_EQ(run_cli("polish classic18 --criterion D --digits 0").status, 2);
  EXPECT_EQ(run_cli("polish --criterion D").status, 2);
  const auto r = run_cli("polish classic18 --criterion D --digits 20 --out /dev/full");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/dev/full"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace scalcal::testing
