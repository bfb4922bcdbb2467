// `scalcal evaluate` and `scalcal catalogue` as a user runs them: the JSON keys the issue fixes,
// and every bad input ends with a one-line message naming the file and exit status 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

const std::string kNine = "1,0,0\n-1,0,0\n0,1,0\n0,-1,0\n0,0,1\n0,0,-1\n1,1,0\n0,1,1\n1,0,1\n";

int count_lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST(EvaluateCli, JsonKeysInOrder) {
  const auto r = run_cli("evaluate classic18 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  std::size_t at = 0;
  for (const char* key : {"positions", "rank", "condition", "D", "A", "E", "S", "theta_bias", "theta_scale",
                          "theta_nonorth", "det_K", "trace_K", "lambda_max_K", "max_diag_K"}) {
    const auto found = r.out.find("\"" + std::string(key) + "\":", at);
    ASSERT_NE(found, std::string::npos) << key << " missing or out of order in\n" << r.out;
    at = found;
  }
  // 17006112 = 81 * 36 * 5832, by hand from the moments of the 18-position program.
  const auto d = r.out.find("\"D\": ");
  ASSERT_NE(d, std::string::npos);
  EXPECT_NEAR(std::stod(r.out.substr(d + 5)), 17006112.0, 1e-6) << r.out;
}

TEST(EvaluateCli, CsvFileAndReadableTable) {
  const auto path = write_file("nine.csv", "x,y,z\n" + kNine);
  const auto r = run_cli("evaluate " + path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("N = 9, rank 9"), std::string::npos) << r.out;
}

struct BadInput {
  std::string name, content, fragment;
  bool with_line;
};

TEST(EvaluateCli, BadInputsExitTwoWithAMessage) {
  const std::vector<BadInput> cases = {
      {"empty.csv", "", "empty file", false},
      {"text.csv", "hello world\nthis is not a program\n", "is not a number", true},
      {"header.csv", "a,b,c\n" + kNine, "header must name columns x,y,z", true},
      {"nan.csv", "x,y,z\n" + kNine + "nan,1,0\n", "not finite", true},
      {"inf.csv", "x,y,z\n" + kNine + "1,-inf,0\n", "not finite", true},
      {"word.csv", "x,y,z\n1,0,zero\n", "is not a number", true},
      {"short.csv", "x,y,z\n1,0,0\n0,1,0\n0,0,1\n", "only 3 positions", false},
      {"zero.csv", "x,y,z\n" + kNine + "0,0,0\n", "zero vector", true},
      {"binary.csv",
       std::string("\x7f"
                   "ELF\0\0\x01",
                   7),
       "not a text file", false},
      {"planar.csv", "x,y,z\n1,0,0\n0,1,0\n-1,0,0\n0,-1,0\n1,1,0\n1,-1,0\n-1,1,0\n-1,-1,0\n2,1,0\n1,2,0\n",
       "rank 5 of 9", false},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const auto path = write_file(c.name, c.content);
    const auto r = run_cli("evaluate " + path);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(count_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(path), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.fragment), std::string::npos) << r.err;
    if (c.with_line) {
      EXPECT_NE(r.err.find(path + ":"), std::string::npos) << r.err;
    }
    EXPECT_TRUE(r.out.empty());
  }
}

TEST(EvaluateCli, RankDeficientMessageNamesTheParameters) {
  const auto r = run_cli("evaluate rotation-4");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("rank 6 of 9"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nonorth_xy, nonorth_yz, nonorth_zx"), std::string::npos) << r.err;
}

// Nearly planar: z = +-1e-3 makes the z^2 column ~1e-6, so H^T H has condition ~1e12. The program
// is still evaluated, with a warning naming the poorly determined parameters.
TEST(EvaluateCli, IllConditionedProgramIsExplained) {
  std::string rows = "x,y,z\n";
  for (int j = 0; j < 12; ++j)
    rows += std::to_string(std::cos(0.5 * j)) + "," + std::to_string(std::sin(0.5 * j)) + "," +
            (j % 3 == 0   ? "0.001"
             : j % 3 == 1 ? "-0.001"
                          : "0.0005") +
            "\n";
  const auto path = write_file("flat.csv", rows);
  const auto r = run_cli("evaluate " + path);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("ill-conditioned"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("scale_z"), std::string::npos) << r.err;
}

TEST(EvaluateCli, MissingFileAndUsageErrors) {
  auto r = run_cli("evaluate /nonexistent/program.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("/nonexistent/program.csv: cannot open file"), std::string::npos) << r.err;
  r = run_cli("evaluate no-such-program");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("neither a catalogue name nor a file"), std::string::npos) << r.err;
  r = run_cli("evaluate classic18 --jsn");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("unknown option --jsn"), std::string::npos) << r.err;
  r = run_cli("evaluate");
  EXPECT_EQ(r.status, 2);
  r = run_cli("no-such-command");
  EXPECT_EQ(r.status, 2);
}

// A model without region limits (axis6) is judged on the sphere: --region sphere restricts nothing, a program
// file's region line (as optimize writes it) is said and set aside, and only a restricted --region is refused.
TEST(EvaluateCli, ModelsWithoutRegionLimitsAreJudgedOnTheSphere) {
  const std::string upper = "1,0,0\n-1,0,0\n0,1,0\n0,-1,0\n0,0,1\n1,1,0\n0,1,1\n1,0,1\n-1,0,1\n";
  const auto tagged = write_file("upper_cap.csv", "# region: cap:90\nx,y,z\n" + upper);
  const auto plain = write_file("upper_plain.csv", "x,y,z\n" + upper);
  const auto from_file = run_cli("evaluate " + tagged + " --model axis6 --json");
  ASSERT_EQ(from_file.status, 0) << from_file.err;
  EXPECT_NE(from_file.err.find("its region line (cap:90) is set aside"), std::string::npos) << from_file.err;
  EXPECT_EQ(count_lines(from_file.err), 1) << from_file.err;
  EXPECT_EQ(from_file.out, run_cli("evaluate " + plain + " --model axis6 --json").out);
  const auto sphere = run_cli("evaluate dodecahedral-12 --model axis6 --region sphere --json");
  ASSERT_EQ(sphere.status, 0) << sphere.err;
  EXPECT_EQ(sphere.out, run_cli("evaluate dodecahedral-12 --model axis6 --json").out);
  const auto cap = run_cli("evaluate dodecahedral-12 --model axis6 --region cap:90");
  EXPECT_EQ(cap.status, 2);
  EXPECT_EQ(count_lines(cap.err), 1) << cap.err;
  EXPECT_NE(cap.err.find("--region has limits for the paper9 model only"), std::string::npos) << cap.err;
  // optimize and sweep likewise: axis6's D limit 729 (six axis directions, each N/6 times) at N = 12.
  for (const char* command : {"optimize --positions 12", "sweep --positions 12 --criteria D"}) {
    const auto r = run_cli(std::string(command) + " --model axis6 --region sphere --starts 2 --json");
    ASSERT_EQ(r.status, 0) << command << ": " << r.err;
    const auto at = r.out.find("\"value\": ");
    ASSERT_NE(at, std::string::npos) << r.out;
    EXPECT_NEAR(std::stod(r.out.substr(at + 9)), 729.0, 1e-6) << r.out;
    EXPECT_EQ(run_cli(std::string(command) + " --model axis6 --region cap:90 --starts 2").status, 2) << command;
  }
}

TEST(CatalogueCli, ListsThePaperPrograms) {
  const auto r = run_cli("catalogue");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* name : {"classic18", "rotation-6", "nine-2axes", "nine-3axes", "octahedral-1-1-0", "dodecahedral-12",
                           "icosahedral-20", "table1-A", "table2-E", "table3-S"})
    EXPECT_NE(r.out.find(name), std::string::npos) << name;
  const auto j = run_cli("catalogue --json");
  ASSERT_EQ(j.status, 0) << j.err;
  EXPECT_NE(j.out.find("\"name\": \"icosahedral-20\""), std::string::npos);
}

}  // namespace
}  // namespace scalcal::testing
