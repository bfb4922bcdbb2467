// Issue 36 item 1: no text reaches gnuplot as a command. A folder name holding every byte 1-255
// (a newline and a `system` command among them) is where the figure is drawn: gnuplot runs there
// with no shell and no folder name in its script, and no marker file appears. Titles and comments
// with line breaks stay inside their strings. (Issue 50: gp_quote is attacked through gnuplot itself
// in tests/robustness/injection_test.cpp.)
#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include "plots/figure.hpp"

namespace fs = std::filesystem;
using scalcal::plots::FigureSpec;

namespace {

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("scalcal_injection_test_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

// Would create `marker` if any of its text ran as a gnuplot command or in a shell.
std::string attack(const fs::path& marker) {
  const std::string m = marker.string();
  return "x'\nsystem \"touch " + m + "\"\n'\" ; touch " + m + " ; $(touch " + m + ") `touch " + m + "`";
}

FigureSpec line_spec(const std::string& title) {
  FigureSpec s;
  s.name = "line";
  s.comment = "injection test\nsystem 'false'";
  s.body = "plot 'line.csv' skip 1 using 1:2 with lines title " + scalcal::plots::gp_quote(title) + "\n";
  return s;
}

TEST(FigureInjection, GpQuoteKeepsEveryByteInsideTheString) {
  for (int b = 1; b < 256; ++b) {
    const std::string q = scalcal::plots::gp_quote(std::string("a") + static_cast<char>(b) + "'b\"");
    ASSERT_EQ(q.front(), '"');
    ASSERT_EQ(q.back(), '"');
    for (std::size_t i = 1; i + 1 < q.size(); ++i) {
      const auto c = static_cast<unsigned char>(q[i]);
      EXPECT_FALSE(c < 0x20 || c == 0x7f || c == '"' || c == '`' || c == '@' || c == '$') << "byte " << b;
    }
  }
}

TEST(FigureInjection, AFolderNameWithEveryByteDrawsAndRunsNothing) {
  const fs::path base = scratch();
  const fs::path marker = base / "PWNED";
  std::string name;
  for (int b = 1; b < 256; ++b)
    if (b != '/') name += static_cast<char>(b);
  for (const std::string& folder : {name, attack(marker)}) {
    const fs::path dir = base / folder;
    fs::create_directories(dir);
    std::ofstream(dir / "line.csv") << "x,y\n0,0\n1,1\n";
    const auto out = scalcal::plots::render(dir, line_spec(attack(marker)));
    EXPECT_TRUE(fs::file_size(out.pdf) > 0);
    EXPECT_FALSE(fs::exists(marker)) << "a folder name or title ran as a command";
    EXPECT_FALSE(fs::exists(dir / "line.gnuplot.log")) << "gnuplot complained";
  }
  fs::remove_all(base);
}

// A name is a file's in the folder: any bytes but '/' (and NUL), not empty.
TEST(FigureInjection, AFigureNameIsAFileInItsFolder) {
  const fs::path base = scratch();
  FigureSpec s = line_spec("t");
  for (const std::string& bad : {std::string("../up"), std::string("a/b"), std::string()}) {
    s.name = bad;
    EXPECT_THROW(scalcal::plots::render(base, s), std::invalid_argument) << bad;
  }
  fs::remove_all(base);
}

}  // namespace
