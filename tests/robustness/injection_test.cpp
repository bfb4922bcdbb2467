// Issue 50 item 1: no user text in a generated script. File names reach gnuplot only as string
// literals of plots::gp_quote (data files by a variable the script sets, outputs as "./NAME"), and
// the quoting is attacked two ways: gnuplot itself reads back every attack text through it (quotes,
// backslashes, newlines, system(), backticks, macros, pipes, non-UTF-8 bytes, every byte 1-255), and
// every subcommand that draws (plot, plot --log; reproduce's figures in tests/plots) is run with such
// names: nothing runs, and the files arrive under the asked name.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "numeric/io/input_error.hpp"
#include "plots/figure.hpp"
#include "tests/common/bad_input.hpp"

namespace scalcal::testing {
namespace {

namespace fs = std::filesystem;

// The file an attack would create, relative: a command runs in gnuplot's folder (the figure's) or in
// the working folder of the CLI; ran() looks in both.
const std::string kMarker = "PWNED_issue50";
bool ran(const fs::path& folder) { return fs::exists(folder / kMarker) || fs::exists(fs::current_path() / kMarker); }

// Texts that would create the marker if any part of them ran: in gnuplot (system(), backticks, a
// pipe as a file or an output, a new line of commands) or in a shell. None holds a '/' (a figure's
// name is a file's, in its folder).
std::vector<std::string> attacks() {
  const std::string m = kMarker;
  // Every byte but '/' (and NUL), in two halves: a file name holds at most 255 bytes.
  std::string low, high;
  for (int b = 1; b < 256; ++b)
    if (b != '/') (b < 128 ? low : high) += static_cast<char>(b);
  return {
      "x'.system('touch " + m + "').'",                   // the issue's stem: out of single quotes
      "x\".system(\"touch " + m + "\").\"",               // out of double quotes
      "a`touch " + m + "`b",                              // command substitution, inside double quotes too
      "n\nsystem \"touch " + m + "\"\n#",                 // a new line of commands
      "b\\\\\"; system(\"touch " + m + "\") #",           // backslashes before a quote
      "@cmd $(touch " + m + ") ;touch " + m,              // a macro, a shell's substitution and separator
      "<touch " + m,                                      // a data file name gnuplot would open as a pipe
      "|touch " + m,                                      // an output gnuplot would open as a pipe
      "esc\x1b[2Jbell\x07 and \xff\xfe\xc3 stray bytes",  // control characters, bytes that are not UTF-8
      "ok \xce\xb8 \xe2\x89\xa5 utf-8 \\",                // valid UTF-8 (kept as it is), a final backslash
      low,
      high,
  };
}

// gnuplot reads every attack back, byte for byte, from gp_quote's literal.
TEST(GnuplotQuoting, GnuplotReadsEveryAttackBackExactly) {
  const fs::path dir = scratch_dir() / "gp_quote";
  fs::create_directories(dir);
  std::string script = "set print " + plots::gp_file("printed.txt") + "\n";
  const auto texts = attacks();
  for (const auto& t : texts) script += "print " + plots::gp_quote(t) + "\nprint " + plots::gp_quote("\x1e") + "\n";
  std::ofstream(dir / "read_back.gp", std::ios::binary) << script;
  const int status =
      std::system(("cd '" + dir.string() + "' && " SCALCAL_GNUPLOT " read_back.gp 2>gnuplot.err").c_str());
  ASSERT_EQ(status, 0) << slurp((dir / "gnuplot.err").string());
  EXPECT_FALSE(ran(dir)) << "an attack ran";
  std::string expected;
  for (const auto& t : texts) expected += t + "\n\x1e\n";
  std::ifstream in(dir / "printed.txt", std::ios::binary);
  const std::string printed((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(printed, expected);
  EXPECT_THROW(plots::gp_quote(std::string("a\0b", 3)), std::invalid_argument);
  EXPECT_THROW(plots::gp_file("sub/dir"), std::invalid_argument);
}

// A program file whose `step` column makes plot draw the run's path (every data file of a plot).
std::string plan_like_program() {
  return write_file("steps.csv",
                    "x,y,z,step\n1,0,0,1\n0,1,0,2\n0,0,1,3\n-1,0,0,4\n0,-1,0,5\n0,0,-1,6\n"
                    "0.6,0.8,0,7\n0,0.6,0.8,8\n0.8,0,0.6,9\n-0.6,0.8,0,10\n0,-0.6,0.8,11\n0.8,0,-0.6,12\n");
}

// The figure's four files are there under the asked stem, non-empty, and no attack ran.
void expect_figure(const fs::path& dir, const std::string& stem, const CliResult& r) {
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* ext : {".gp", ".pdf", ".png", ".svg"}) {
    std::error_code ec;
    EXPECT_GT(fs::file_size(dir / (stem + ext), ec), 0u) << ext << ": " << ec.message();
  }
  EXPECT_FALSE(ran(dir)) << "an attack ran";
  EXPECT_FALSE(fs::exists(dir / (stem + ".gnuplot.log"))) << "gnuplot complained";
}

// Every attack as --out's stem (the hemispheres with the run's path), and a few with a shaded region
// (its pixels and edges: every data file a figure reads) and in the cap view. `plot` draws in the
// folder of --out: the folder is one the test makes.
TEST(PlotInjection, EveryAttackAsTheFigureName) {
  const fs::path dir = scratch_dir() / "plot_attacks";
  fs::create_directories(dir);
  const std::string program = quote(plan_like_program());
  const auto texts = attacks();
  for (std::size_t i = 0; i < texts.size(); ++i) {
    const std::string stem = std::to_string(i) + texts[i];
    SCOPED_TRACE(display_name(stem));
    expect_figure(dir, stem, run_limited("plot " + program + " --out " + quote((dir / (stem + ".pdf")).string())));
    if (i != 1) continue;
    for (const std::string region : {"faces:30", "cap:80"}) {
      const std::string also = stem + region.substr(0, 3);
      expect_figure(
          dir, also,
          run_limited("plot " + program + " --region " + region + " --out " + quote((dir / (also + ".svg")).string())));
    }
  }
}

// The same for plot --log, and with the log's and the calibration's file names as attacks too.
TEST(PlotInjection, LogFigureWithAttackNames) {
  const fs::path dir = scratch_dir() / "plot_log_attacks";
  fs::create_directories(dir);
  const std::string log = (dir / ("log" + attacks()[0] + ".csv")).string();
  const std::string cal = (dir / ("cal" + attacks()[3] + ".json")).string();
  ASSERT_EQ(run_limited("simulate --program classic18 --noise 1e-3 --dwell 2 --still 10 --rate 50 --log " + quote(log))
                .status,
            0);
  const CliResult c = run_limited("calibrate --magnitude 1 --measurements " + quote(log) + " --out " + quote(cal));
  ASSERT_EQ(c.status, 0) << c.err;
  for (const std::string& attack : {attacks()[1], attacks()[6], attacks()[8]}) {
    SCOPED_TRACE(display_name(attack));
    const std::string stem = "L" + attack;
    expect_figure(dir, stem,
                  run_limited("plot --log " + quote(log) + " --calibration " + quote(cal) + " --out " +
                              quote((dir / (stem + ".png")).string())));
  }
}

}  // namespace
}  // namespace scalcal::testing
