// The classes a bad input may end in, and the runner that asserts them (tests/robustness/):
//   error  exit 2, exactly one line on stderr naming the file or option and the reason;
//   warn   exit 0, a result on stdout and one warning line on stderr;
//   same   exit 0, the same result as a clean reference input (BOM, CRLF, CR files);
//   write  exit 1, one line naming the file that could not be written.
// Every case checks the exit status and words of its message, so each one fails if the command
// hangs (killed at 60 s: status 137), crashes (internal error, exit 1, or a signal), accepts the
// input silently (exit 0) or gives an unhelpful message.
#pragma once
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "tests/common/run_cli.hpp"

namespace scalcal::testing {

enum class Expect { error, warn, same, write };

struct Case {
  std::string name;                   // the test's name
  std::function<std::string()> args;  // generates its inputs, returns the CLI arguments
  Expect expect;
  std::vector<std::string> needles;        // words the message (error, warn, write) must contain
  std::function<std::string()> reference;  // for `same`: the arguments of the clean input

  Case(std::string n, std::function<std::string()> a, Expect e, std::vector<std::string> words,
       std::function<std::string()> clean = {})
      : name(std::move(n)), args(std::move(a)), expect(e), needles(std::move(words)), reference(std::move(clean)) {}
};

// gcc defines __SANITIZE_ADDRESS__; clang (scripts/sanitize.sh builds with it) answers __has_feature.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// run_cli with a wall-clock limit (a hang is a failure, not a stuck test) and a memory limit
// (a huge allocation fails at once instead of swapping). Under AddressSanitizer, which reserves
// terabytes of address space for its shadow memory, the limit is ASan's own allocation check.
inline CliResult run_limited(const std::string& args) {
  static int counter = 0;
  const auto base = (scratch_dir() / ("limited" + std::to_string(counter++))).string();
  const std::string limit = kAddressSanitizer ? "" : "ulimit -v 8000000; ";
  const std::string cmd = limit + "exec timeout -s KILL 60 " + std::string(SCALCAL_CLI) + " " + args + " >" + base +
                          ".out 2>" + base + ".err </dev/null";
  const int raw = std::system(cmd.c_str());
  CliResult r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(base + ".out");
  r.err = slurp(base + ".err");
  return r;
}

inline int lines(const std::string& s) { return static_cast<int>(std::count(s.begin(), s.end(), '\n')); }

// A shell word in single quotes, whatever bytes it holds ('\'' for a quote).
inline std::string quote(const std::string& path) {
  std::string q = "'";
  for (char c : path) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

inline void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

// Runs the case and asserts its class and words.
inline void expect_class(const Case& c) {
  const FixedDate date;  // a case that should print the same as its reference, calibrate --json among them
  const std::string args = c.args();
  const CliResult r = run_limited(args);
  const std::string shown = args.size() > 300 ? args.substr(0, 300) + "..." : args;
  SCOPED_TRACE(shown);
  ASSERT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  switch (c.expect) {
    case Expect::error:
      EXPECT_EQ(r.status, 2) << r.err;
      EXPECT_TRUE(r.out.empty()) << r.out;
      break;
    case Expect::warn:
      EXPECT_EQ(r.status, 0) << r.err;
      EXPECT_FALSE(r.out.empty());
      break;
    case Expect::same: {
      EXPECT_EQ(r.status, 0) << r.err;
      EXPECT_EQ(r.err, "");
      const CliResult ref = run_limited(c.reference());
      ASSERT_EQ(ref.status, 0) << ref.err;
      EXPECT_EQ(r.out, ref.out);
      return;
    }
    case Expect::write:
      EXPECT_EQ(r.status, 1) << r.err;
      break;
  }
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("scalcal ", 0), 0u) << r.err;
  for (const auto& n : c.needles) EXPECT_NE(r.err.find(n), std::string::npos) << "missing '" << n << "' in: " << r.err;
}

}  // namespace scalcal::testing
