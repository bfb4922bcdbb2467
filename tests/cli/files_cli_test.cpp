// Files as people have them, through the CLI (issue 33): a program or bench file written with
// quotes, ';', upper-case headers or text position labels gives the same result as the plain
// file; "-" reads standard input and `--out -` writes standard output (the report then goes to
// stderr); random, jig, limits and simulate write what they produce with --out.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <vector>

#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

// Runs `scalcal ARGS` with the file `input` on its standard input.
CliResult run_with_stdin(const std::string& input, const std::string& args) {
  static int counter = 0;
  const auto base = scratch_dir() / ("stdin" + std::to_string(counter++));
  const std::string cmd = "cat '" + input + "' | " + std::string(SCALCAL_CLI) + " " + args + " >" + base.string() +
                          ".out 2>" + base.string() + ".err";
  const int raw = std::system(cmd.c_str());
  CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(base.string() + ".out");
  r.err = slurp(base.string() + ".err");
  return r;
}

// The program `evaluate` writes for FILE (normalised directions and their angles).
std::string evaluated(const std::string& file, const std::string& out) {
  const auto r = run_cli("evaluate " + file + " --out " + (scratch_dir() / out).string());
  EXPECT_EQ(r.status, 0) << r.err;
  return slurp((scratch_dir() / out).string());
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

const char* kPlain = "x,y,z\n1,0,0\n-1,0,0\n0,1,0\n0,-1,0\n0,0,1\n0,0,-1\n1,1,0\n0,1,1\n1,0,1\n0.5,-1,2\n";

TEST(FilesCli, QuotedSemicolonAndUpperCaseProgramsReadAsPlain) {
  const std::string plain = evaluated(write_file("plain.csv", kPlain), "plain_out.csv");
  const std::string quoted = write_file("quoted.csv",
                                        "\"X\",\"Y\",\"Z\"\n\"1\",\"0\",\"0\"\n-1,0,0\n0,1,0\n0,-1,0\n0,0,1\n0,0,-1\n1,"
                                        "1,0\n0,1,1\n1,0,1\n\"0.5\",-1,2\n");
  EXPECT_EQ(evaluated(quoted, "quoted_out.csv"), plain);
  const std::string semicolon = write_file(
      "semicolon.csv", "x;y;z\n1;0;0\n-1;0;0\n0;1;0\n0;-1;0\n0;0;1\n0;0;-1\n1;1;0\n0;1;1\n1;0;1\n0,5;-1;2\n");
  EXPECT_EQ(evaluated(semicolon, "semicolon_out.csv"), plain);
  const auto bad = run_cli("evaluate " + write_file("bad.csv", "x;y;z\n1;0;0\n1.000,5;0;0\n"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_TRUE(std::regex_search(bad.err, std::regex("bad\\.csv:3: '1\\.000,5' in column x is not a number")))
      << bad.err;
}

TEST(FilesCli, StandardInputIsDash) {
  const std::string file = write_file("stdin_plain.csv", kPlain);
  const std::string plain = evaluated(file, "stdin_plain_out.csv");
  const auto r = run_with_stdin(file, "evaluate - --out " + (scratch_dir() / "from_stdin.csv").string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp((scratch_dir() / "from_stdin.csv").string()), plain);
  EXPECT_NE(r.out.find("program -: N = 10"), std::string::npos) << r.out;
  // Standard input is read once and kept: a program's region line and its rows both come from it.
  // classic18 (the six axes and the twelve edge midpoints) has only +z within 10 degrees of +z.
  const auto classic = run_cli("evaluate classic18 --out -");
  ASSERT_EQ(classic.status, 0) << classic.err;
  const std::string capped = write_file("cap10.csv", "# region: cap:10\n" + classic.out);
  const auto region = run_with_stdin(capped, "evaluate -");
  EXPECT_EQ(region.status, 2);
  EXPECT_NE(region.err.find("-: 17 of 18 positions are outside the region cap:10"), std::string::npos) << region.err;
  // A defect on standard input names it as the user did, "-", with the line.
  const auto bad = run_with_stdin(write_file("stdin_bad.csv", "x,y,z\n1,0,zero\n"), "evaluate -");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("-:2: 'zero' in column z is not a number"), std::string::npos) << bad.err;
}

TEST(FilesCli, OutDashIsStandardOutput) {
  const std::string file = write_file("dash_plain.csv", kPlain);
  const std::string plain = evaluated(file, "dash_plain_out.csv");
  const auto r = run_cli("evaluate " + file + " --out -");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, plain);                                              // the file alone on stdout
  EXPECT_NE(r.err.find("N = 10, rank 9"), std::string::npos) << r.err;  // the report on stderr
  const auto two = run_cli("simulate --program classic18 --noise 0.001 --log - --truth -");
  EXPECT_EQ(two.status, 2);
  EXPECT_NE(two.err.find("--log and --truth both write to standard output"), std::string::npos) << two.err;
}

// The same bench file with positions numbered 1..18 and labelled P1..P18 calibrates to the same
// JSON (positions are grouped in order of first appearance either way).
TEST(FilesCli, TextPositionLabelsCalibrateAsNumbers) {
  const std::string numbered = (scratch_dir() / "bench_numbered.csv").string();
  const auto made =
      run_cli("simulate --program classic18 --noise 0.001 --seed 3 --rate 10 --dwell 1 --bench-file " + numbered);
  ASSERT_EQ(made.status, 0) << made.err;
  std::istringstream in(slurp(numbered));
  std::string labelled;
  int data_rows = 0;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] >= '0' && line[0] <= '9') {
      line = "\"P" + line.substr(0, line.find(',')) + "\"" + line.substr(line.find(','));
      ++data_rows;
    }
    labelled += line + "\n";
  }
  ASSERT_EQ(data_rows, 180);
  const std::string labels = write_file("bench_labelled.csv", labelled);
  const FixedDate date;  // the two --json documents state when they were made
  const auto a = run_cli("calibrate --measurements " + numbered + " --magnitude 1 --json");
  const auto b = run_cli("calibrate --measurements " + labels + " --magnitude 1 --json");
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(b.out, a.out);
  // `correct` keeps each row's label where it kept the number: the same rows, P prefixed.
  const std::string cal = (scratch_dir() / "labels_cal.json").string();
  ASSERT_EQ(run_cli("calibrate --measurements " + numbered + " --magnitude 1 --out " + cal).status, 0);
  const auto by_number = lines_of(run_cli("correct --calibration " + cal + " --measurements " + numbered).out);
  const auto by_label = lines_of(run_cli("correct --calibration " + cal + " --measurements " + labels).out);
  ASSERT_EQ(by_label.size(), 181u);
  ASSERT_EQ(by_number.size(), 181u);
  EXPECT_EQ(by_label[0], by_number[0]);
  for (std::size_t k = 1; k < by_label.size(); ++k) EXPECT_EQ(by_label[k], "P" + by_number[k]) << k;
}

// The number after "key": in a JSON text (the first one).
double json_number(const std::string& json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(json, m, std::regex("\"" + key + "\": ([-+0-9.eE]+)"))) return std::nan("");
  return std::stod(m[1]);
}

// D of a program file by `evaluate`: the other half of the toolkit checks what was written.
double evaluated_d(const std::string& file) {
  const auto r = run_cli("evaluate " + file + " --json");
  EXPECT_EQ(r.status, 0) << r.err;
  return json_number(r.out, "D");
}

TEST(FilesCli, RandomAndJigWriteTheirProgram) {
  const std::string random = (scratch_dir() / "random.csv").string();
  const auto r = run_cli("random --positions 9 --count 2000 --seed 1 --json --out " + random);
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_EQ(lines_of(slurp(random)).size(), 10u);  // header and 9 positions
  EXPECT_NEAR(evaluated_d(random) / json_number(r.out, "best"), 1.0, 1e-9);

  const std::string jig = (scratch_dir() / "jig.csv").string();
  const auto j = run_cli("jig cuboctahedron --json --out " + jig);
  ASSERT_EQ(j.status, 0) << j.err;
  ASSERT_EQ(lines_of(slurp(jig)).size(), 15u);  // 8 triangles and 6 squares
  EXPECT_NEAR(evaluated_d(jig) / json_number(j.out, "value"), 1.0, 1e-9);
}

TEST(FilesCli, LimitsWriteTheirTable) {
  const std::string file = (scratch_dir() / "limits.csv").string();
  const auto r = run_cli("limits --out " + file);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = lines_of(slurp(file));
  ASSERT_GE(rows.size(), 3u);
  EXPECT_EQ(rows[0], "criterion,limit,exact,lower_bound");
  EXPECT_EQ(rows[1], "D,15377343.75,\"61509375/4\",");  // the paper's D limit, 61509375/4
  ASSERT_EQ(rows[2].rfind("A,", 0), 0u) << rows[2];
  EXPECT_NEAR(std::stod(rows[2].substr(2)), 45 + 18 * std::sqrt(2.0), 1e-12);
  EXPECT_NE(rows[2].find(",\"45+18*sqrt(2)\","), std::string::npos) << rows[2];
}

TEST(FilesCli, SimulateWritesItsTable) {
  const std::string file = (scratch_dir() / "simulate.csv").string();
  const auto r = run_cli("simulate --program classic18 --noise 0.001 --trials 20 --seed 1 --json --out " + file);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = lines_of(slurp(file));
  ASSERT_EQ(rows.size(), 19u);  // header, 9 parameters for each of the two moduli
  EXPECT_EQ(rows[0], "modulus,parameter,truth,bias,standard_error,linear_error,empirical_std,theoretical_std");
  EXPECT_EQ(rows[1].rfind("norm,bias_x,0.001,", 0), 0u) << rows[1];  // --size 0.001: the true bias
  EXPECT_EQ(rows[10].rfind("projection,bias_x,", 0), 0u) << rows[10];
  const auto rehearsal = run_cli("simulate --program classic18 --noise 0.001 --log /dev/null --out " + file);
  EXPECT_EQ(rehearsal.status, 2);
  EXPECT_NE(rehearsal.err.find("--out belongs to the Monte-Carlo"), std::string::npos) << rehearsal.err;
}

}  // namespace
}  // namespace scalcal::testing
