// The CLI's contract for options: help and version, every option documented with its unit and
// default, and every malformed value rejected in one line that names the option, with exit 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <regex>
#include <sstream>

#include "tests/common/run_cli.hpp"

namespace scalcal::testing {
namespace {

const char* const kCommands[] = {"catalogue", "evaluate", "calibrate", "optimize", "random", "simulate",
                                 "sweep",     "polish",   "reproduce", "family",   "limits", "jig"};

int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

TEST(OptionsCli, VersionComesFromTheProject) {
  const auto r = run_cli("--version");
  EXPECT_EQ(r.status, 0);
  // "scalcal 0.1 (commit 3f2c1a9b0d4e, Release build)": the project's version, then git describe's
  // commit (or "unknown" outside a git tree) and CMake's build type.
  EXPECT_TRUE(std::regex_match(r.out, std::regex("scalcal 0\\.1 \\(commit [^ ,()]+, [A-Za-z]+ build\\)\n"))) << r.out;
}

TEST(OptionsCli, HelpListsEveryCommand) {
  const auto r = run_cli("help");
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* c : kCommands) EXPECT_NE(r.out.find(std::string("\n  ") + c), std::string::npos) << c;
  EXPECT_EQ(run_cli("--help").out, r.out);
  EXPECT_EQ(run_cli("").status, 2);  // no command: the overview on stderr
}

TEST(OptionsCli, UnknownCommandsAndTopLevelOptionsExitTwo) {
  auto r = run_cli("--bogus");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "scalcal: unknown option --bogus (try `scalcal help`)\n");
  r = run_cli("help nosuch");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("nosuch"), std::string::npos) << r.err;
}

// Every option that takes a value states its unit and its default (or that it is required); a
// switch only says what it does.
TEST(OptionsCli, EveryOptionShowsItsUnitAndDefault) {
  for (const char* c : kCommands) {
    SCOPED_TRACE(c);
    const auto r = run_cli(std::string(c) + " --help");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(run_cli(std::string(c) + " -h").out, r.out);
    EXPECT_EQ(run_cli(std::string("help ") + c).out, r.out);
    std::istringstream in(r.out);
    int options = 0;
    for (std::string line; std::getline(in, line);) {
      const auto first = line.find_first_not_of(' ');
      if (first == std::string::npos || first == 0 || line[first] != '-') continue;
      ++options;
      std::string text = line;  // CLI11 may wrap a long description onto following indented lines
      for (auto at = in.tellg(); true; at = in.tellg()) {
        std::string more;
        if (!std::getline(in, more)) break;
        const auto f = more.find_first_not_of(' ');
        if (f == std::string::npos || f == 0 || more[f] == '-') {
          in.seekg(at);
          break;
        }
        text += more;
      }
      // The token after the name is a value name (N, FILE, A..B, KEY=VALUE, auto|ipopt) or the help text.
      std::istringstream words(text.substr(first));
      std::string name, token;
      words >> name >> token;
      const bool takes_value = token.find('|') != std::string::npos ||
                               (!token.empty() && std::isupper(static_cast<unsigned char>(token[0])));
      if (!takes_value) {
        EXPECT_EQ(text.find("unit: "), std::string::npos) << text;
        continue;
      }
      EXPECT_NE(text.find("unit: "), std::string::npos) << text;
      EXPECT_TRUE(text.find("default: ") != std::string::npos || text.find("required)") != std::string::npos) << text;
    }
    EXPECT_GE(options, 2) << r.out;  // --help and at least one more
  }
}

TEST(OptionsCli, ThreadsIsDocumentedWhereWorkRunsInParallel) {
  for (const char* c : {"optimize", "random", "sweep", "reproduce"})
    EXPECT_NE(run_cli(std::string(c) + " --help").out.find("--threads"), std::string::npos) << c;
}

struct Bad {
  std::string args, option, reason;
};

TEST(OptionsCli, MalformedValuesNameTheOptionAndExitTwo) {
  const std::string sim = "simulate --program classic18 --trials 10 ";
  const Bad cases[] = {
      {"optimize --positions 9abc", "--positions", "integer"},
      {"optimize --positions ''", "--positions", "integer"},
      {"optimize --positions 12.5", "--positions", "integer"},
      {"optimize --positions 1001", "--positions", "3..1000"},
      {"optimize --positions 12 --seed -1", "--seed", "integer"},
      {"optimize --positions 12 --digits 0x10", "--digits", "integer"},
      {"optimize --positions 12 --criterion Q", "--criterion", "D, A, E or S"},
      {"random --positions 12 --count 10x", "--count", "integer"},
      {"sweep --criteria ''", "--criteria", "D, A, E, S"},
      {"sweep --criteria D,", "--criteria", "D, A, E, S"},
      {"sweep --positions ''", "--positions", "A..B"},
      {"sweep --positions 12..10", "--positions", "A..B"},
      {"sweep --positions 9..12x", "--positions", "A..B"},
      {sim + "--noise -1", "--noise", "must be positive"},
      {sim + "--noise 0", "--noise", "must be positive"},
      {sim + "--noise 1e-3x", "--noise", "number"},
      {sim + "--noise nan", "--noise", "number"},
      {sim + "--noise 1e-3 --bench-error 31", "--bench-error", "0..30"},
      {"calibrate --measurements m.csv --magnitude -9.8", "--magnitude", "positive"},
      {"evaluate classic18 --out ''", "--out", "empty"},
      {"evaluate classic18 --out", "--out", "missing"},
      {"evaluate classic18 --jsn", "--jsn", "unknown option"},
      {"evaluate classic18 extra", "extra", "unexpected argument"},
      {"optimize --criterion D", "--positions", "required"},
      {"polish classic18", "--criterion", "required"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.args);
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.option), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(c.reason), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

// CLI11 alone reads integers with base prefixes: "012" would be the octal 10.
TEST(OptionsCli, IntegersAreDecimal) {
  const auto r = run_cli("random --positions 012 --count 1 --json");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto program = r.out.substr(r.out.find("\"program\""));
  EXPECT_EQ(std::count(program.begin(), program.end(), '['), 1 + 12) << r.out;
}

}  // namespace
}  // namespace scalcal::testing
