// `scalcal reproduce --quick --out DIR`: every figure file exists (PDF and PNG by their signatures,
// SVG by its root element) at its stated print width, no figure repeats its caption as a title, the
// CSVs parse, and numbers in them match closed forms derived by hand: classic18 (Fig. 1) has N^9 det K
// = 17006112 and the icosahedral jig 61509375/4. Progress reaches a log as plain lines; --quiet
// silences it.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/common/number_text.hpp"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Minimal CSV (no quoted commas in the cells these tests read).
std::vector<std::map<std::string, std::string>> read_csv(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string>> rows;
  auto split = [](const std::string& l) {
    std::vector<std::string> out;
    std::string cell;
    bool quoted = false;
    for (char c : l) {
      if (c == '"')
        quoted = !quoted;
      else if (c == ',' && !quoted)
        out.push_back(cell), cell.clear();
      else
        cell += c;
    }
    out.push_back(cell);
    return out;
  };
  if (!std::getline(in, line)) return rows;
  header = split(line);
  while (std::getline(in, line)) {
    const auto cells = split(line);
    EXPECT_EQ(cells.size(), header.size()) << p << ": " << line;
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < cells.size() && i < header.size(); ++i) row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

// A shell word in single quotes, whatever bytes it holds.
std::string shell_word(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Issue 50 item 1: the figures are drawn into a folder whose name would run a command if any text of
// it reached a gnuplot script or a shell (quotes, system(), backticks, a new line, $( )).
const char* const kMarker = "PWNED_issue50";

class ReproduceQuick : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    base_ = fs::temp_directory_path() / ("scalcal_reproduce_test_" + std::to_string(::getpid()));
    dir_ = base_ / (std::string("out x'.system('touch ") + kMarker + "').'\n`touch " + kMarker + "` $(touch " +
                    kMarker + ") \"@m\xff");
    fs::remove_all(base_);
    fs::create_directories(base_);
    const std::string cmd = "cd " + shell_word(base_.string()) + " && " + std::string(SCALCAL_CLI) +
                            " reproduce --quick --out " + shell_word(dir_.string()) + " > " +
                            shell_word(base_.string() + "/reproduce.log") + " 2>&1";
    status_ = std::system(cmd.c_str());
  }
  static void TearDownTestSuite() { fs::remove_all(base_); }
  static std::string log() { return slurp(base_ / "reproduce.log"); }
  static fs::path base_, dir_;
  static int status_;
};
fs::path ReproduceQuick::base_;
fs::path ReproduceQuick::dir_;
int ReproduceQuick::status_ = -1;

TEST_F(ReproduceQuick, ExitsCleanly) { EXPECT_EQ(status_, 0) << log(); }

TEST_F(ReproduceQuick, NoTextOfTheFolderRan) {
  for (const fs::path& where : {base_, dir_, fs::current_path()}) EXPECT_FALSE(fs::exists(where / kMarker)) << where;
}

const char* const kFigures[] = {"fig4", "fig5", "fig6", "fig7", "fig8", "fig9", "fig10", "fig11", "fig12", "fig13"};

TEST_F(ReproduceQuick, EveryFigureHasPdfPngSvgAndScript) {
  for (const char* stem : kFigures) {
    const std::string pdf = slurp(dir_ / (std::string(stem) + ".pdf"));
    ASSERT_GT(pdf.size(), 1000u) << stem;
    EXPECT_EQ(pdf.substr(0, 5), "%PDF-") << stem;
    EXPECT_NE(pdf.find("%%EOF"), std::string::npos) << stem;
    const std::string png = slurp(dir_ / (std::string(stem) + ".png"));
    ASSERT_GT(png.size(), 1000u) << stem;
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8)) << stem;
    const std::string svg = slurp(dir_ / (std::string(stem) + ".svg"));
    EXPECT_NE(svg.find("<svg"), std::string::npos) << stem;
    EXPECT_NE(svg.find("</svg>"), std::string::npos) << stem;
    EXPECT_NE(slurp(dir_ / (std::string(stem) + ".gp")).find("plot"), std::string::npos) << stem;
  }
}

// Each script states the width it is drawn for (one column, 85 mm, or two, 175 mm), and its PNG is
// that width at 300 pixels per inch, so the text printed at that width keeps its size in points.
TEST_F(ReproduceQuick, FiguresAreDrawnForAJournalColumn) {
  for (const char* stem : kFigures) {
    const std::string gp = slurp(dir_ / (std::string(stem) + ".gp"));
    const bool one = gp.find("# intended print width: 85 mm (one journal column)") != std::string::npos;
    const bool two = gp.find("# intended print width: 175 mm (two journal columns)") != std::string::npos;
    EXPECT_TRUE(one || two) << stem << ":\n" << gp.substr(0, 400);
    const std::string png = slurp(dir_ / (std::string(stem) + ".png"));
    ASSERT_GT(png.size(), 24u) << stem;
    const unsigned width = (static_cast<unsigned char>(png[16]) << 24) | (static_cast<unsigned char>(png[17]) << 16) |
                           (static_cast<unsigned char>(png[18]) << 8) | static_cast<unsigned char>(png[19]);
    EXPECT_EQ(width, one ? 1004u : 2067u) << stem;
  }
}

// REPORT.md captions every figure; a title inside the image would say it twice (panel labels such as
// "(a)" are labels, not titles).
TEST_F(ReproduceQuick, FiguresHaveNoTitleOfTheirOwn) {
  for (const char* stem : kFigures) {
    const std::string gp = slurp(dir_ / (std::string(stem) + ".gp"));
    EXPECT_EQ(gp.find("set title"), std::string::npos) << stem;
    EXPECT_EQ(std::regex_search(gp, std::regex("multiplot[^\\n]* title ")), false) << stem;
  }
}

// The limits print as mathematics, not as code.
TEST_F(ReproduceQuick, LimitsAreWrittenAsMathematics) {
  const std::string gp = slurp(dir_ / "fig10.gp");
  EXPECT_EQ(gp.find("sqrt("), std::string::npos);
  EXPECT_NE(gp.find("45 + 18√2"), std::string::npos);
}

// The PDF section of a figure's script (the PNG and SVG sections repeat it with other terminals).
std::string pdf_section(const std::string& gp) {
  const auto start = gp.find("# ---- pdf ----"), end = gp.find("# ---- png ----");
  return start == std::string::npos ? std::string() : gp.substr(start, end - start);
}

// Issue 33's figure layout, as the scripts state it. fig5 carries its own key of the program classes;
// fig7's and fig8's θ axes say their unit; fig8's two panels share one y range.
TEST_F(ReproduceQuick, FiguresFiveSevenEightStateKeyUnitAndScale) {
  const std::string fig5 = pdf_section(slurp(dir_ / "fig5.gp"));
  EXPECT_EQ(fig5.find("unset key"), std::string::npos);
  for (const char* t :
       {"title \"uniform\"", "title \"rotation [12]\"", "title \"optimised for D\"", "title \"printable jigs\""})
    EXPECT_NE(fig5.find(t), std::string::npos) << t;
  EXPECT_EQ(std::regex_search(pdf_section(slurp(dir_ / "fig7.gp")), std::regex("set ylabel \"θ[^\n]*per unit σ")),
            true);
  const std::string fig8 = pdf_section(slurp(dir_ / "fig8.gp"));
  EXPECT_NE(fig8.find("per unit σ"), std::string::npos);
  const std::regex range("set yrange \\[0:([^\\]]+)\\]");
  std::vector<std::string> tops;
  for (auto it = std::sregex_iterator(fig8.begin(), fig8.end(), range); it != std::sregex_iterator(); ++it)
    tops.push_back((*it)[1]);
  ASSERT_EQ(tops.size(), 2u);
  EXPECT_EQ(tops[0], tops[1]);
  EXPECT_EQ(fig8.find("[12] 60°"), std::string::npos);  // the cryptic labels are gone
}

// fig10 writes D's unit as fig6 does ("/ 10^7", never "(10^7)") and prints every tick of a panel with
// the same number of decimals ('%.2f'), never '%g' (12, 12.05, 12.1).
TEST_F(ReproduceQuick, FigTenHasOneUnitAndTickConvention) {
  const std::string fig10 = pdf_section(slurp(dir_ / "fig10.gp"));
  EXPECT_NE(fig10.find("det K / 10^{/*1.1 7}"), std::string::npos);
  EXPECT_EQ(fig10.find("(10^"), std::string::npos);
  EXPECT_EQ(fig10.find("format y '%g'"), std::string::npos);
  const std::regex format("set format y '%\\.[0-9]f'");
  EXPECT_EQ(std::distance(std::sregex_iterator(fig10.begin(), fig10.end(), format), std::sregex_iterator()), 4);
}

// fig11 is a flat tilt-azimuth map (no perspective view to hide positions behind others); fig13 has
// no key outside its frames and draws its tics in front of the shaded intervals.
TEST_F(ReproduceQuick, FigElevenAndThirteenHideNothing) {
  const std::string fig11 = pdf_section(slurp(dir_ / "fig11.gp"));
  EXPECT_EQ(fig11.find("splot"), std::string::npos);
  EXPECT_NE(fig11.find("tilt(z)"), std::string::npos);
  const std::string fig13 = pdf_section(slurp(dir_ / "fig13.gp"));
  EXPECT_EQ(fig13.find("key outside"), std::string::npos);
  EXPECT_NE(fig13.find("set tics front"), std::string::npos);
}

// stderr is a log here, not a terminal: one line per stage with the time left, no carriage returns.
TEST_F(ReproduceQuick, ProgressReachesALogAsLines) {
  const std::string log = ReproduceQuick::log();
  EXPECT_EQ(log.find('\r'), std::string::npos);
  EXPECT_NE(log.find("[reproduce] 1/13 analytic programs"), std::string::npos) << log;
  EXPECT_NE(log.find("[reproduce] 13/13 summary"), std::string::npos) << log;
  EXPECT_NE(log.find(" left\n"), std::string::npos) << log;
}

TEST_F(ReproduceQuick, ReportEmbedsFiguresAndStatesThePapersNumbers) {
  const std::string md = slurp(dir_ / "REPORT.md");
  for (const char* s : {"fig4.png", "fig6.png", "fig9.png", "1.538e7", "9, 10, 11, 13, 15", "Table 3"})
    EXPECT_NE(md.find(s), std::string::npos) << s;
}

// Closed-form values stay exact in the report: the optimised N = 12 program reaches the D limit
// 61509375/4 = 15377343.75, which must not print as 15377344, and the E limit 12 prints once.
TEST_F(ReproduceQuick, ReportPrintsExactNumbersExactly) {
  const std::string md = slurp(dir_ / "REPORT.md");
  EXPECT_NE(md.find("61509375/4 = 15377343.75"), std::string::npos);
  EXPECT_NE(md.find("| 12 | 15377343.75 |"), std::string::npos);
  EXPECT_EQ(md.find("15377344"), std::string::npos);
  EXPECT_EQ(md.find("12 = 12"), std::string::npos);
  EXPECT_NE(md.find("Limit of E for N → ∞: 12."), std::string::npos);
  EXPECT_NE(md.find("Limit of A for N → ∞: 45+18*sqrt(2) = 70.455844"), std::string::npos);
}

// Timings carry three significant digits, not the clock's nine, and an optimum equal to the limit up
// to rounding reads "0 (to rounding)", not -9.44e-15 (issue 33: both were shown as data).
TEST_F(ReproduceQuick, ReportShowsNoClockDigitsOrRoundingNoise) {
  const std::string md = slurp(dir_ / "REPORT.md");
  std::istringstream run(md.substr(md.find("## Run")));
  int timings = 0;
  for (std::string line; std::getline(run, line);) {
    std::smatch m;  // the seconds cell of a stage row
    if (!std::regex_search(line, m, std::regex("\\| ([0-9.]+) \\|$"))) continue;
    const std::string digits = std::regex_replace(m[1].str(), std::regex("^[0.]+|\\."), "");
    EXPECT_LE(digits.size(), 3u) << line;
    ++timings;
  }
  EXPECT_GE(timings, 10);
  EXPECT_FALSE(std::regex_search(md, std::regex("\\| -?[0-9.]+e-1[3-9] \\|"))) << "rounding noise shown as data";
  EXPECT_NE(md.find("| 12 | 15377343.75 | 0 (to rounding) | reaches |"), std::string::npos);
}

TEST_F(ReproduceQuick, CsvNumbersAreShortest) {
  for (const char* f : {"fig4_programs.csv", "fig4_random.csv", "fig10.csv", "tables.csv"})
    EXPECT_EQ(scalcal::testing::overlong_numbers(slurp(dir_ / f)), std::vector<std::string>{}) << f;
}

TEST_F(ReproduceQuick, ClosedFormsInTheCsv) {
  const auto rows = read_csv(dir_ / "fig4_programs.csv");
  ASSERT_FALSE(rows.empty());
  bool classic = false, icosa = false;
  for (const auto& r : rows) {
    if (r.at("name") == "octahedral-1-1-0") {
      classic = true;
      EXPECT_NEAR(std::stod(r.at("D")), 17006112.0, 17006112.0 * 1e-12);
      EXPECT_NEAR(std::stod(r.at("theta_bias")), std::sqrt(3.0), 1e-12);
    }
    if (r.at("name") == "icosahedral-20") {
      icosa = true;
      EXPECT_NEAR(std::stod(r.at("D")), 61509375.0 / 4, 61509375.0 / 4 * 1e-12);
    }
  }
  EXPECT_TRUE(classic);
  EXPECT_TRUE(icosa);
  // The registry's printable jigs are drawn beside the paper's two: the rhombic dodecahedron's 12
  // faces are the edge positions, D = 81/((1/3 - 3b)^2 b^3) at b = 1/12 = 20155392 by hand; the
  // icosidodecahedron is a 5-design, at the limit.
  bool rhombic = false, icosidodeca = false;
  for (const auto& r : rows) {
    if (r.at("name") == "jig:rhombic-dodecahedron") {
      rhombic = true;
      EXPECT_NEAR(std::stod(r.at("D")), 20155392.0, 20155392.0 * 1e-12);
    }
    if (r.at("name") == "jig:icosidodecahedron") {
      icosidodeca = true;
      EXPECT_NEAR(std::stod(r.at("D")), 61509375.0 / 4, 61509375.0 / 4 * 1e-12);
    }
  }
  EXPECT_TRUE(rhombic);
  EXPECT_TRUE(icosidodeca);
  for (const char* f : {"fig4_random.csv", "fig8a.csv", "fig8b.csv", "fig9.csv", "fig9_cov.csv", "tables.csv"})
    EXPECT_FALSE(read_csv(dir_ / f).empty()) << f;
  // The random line lies above the limit everywhere (the limit bounds every finite program).
  for (const auto& r : read_csv(dir_ / "fig4_random.csv")) EXPECT_GE(std::stod(r.at("D")), 61509375.0 / 4);
}

// --quiet: the run writes its files and nothing on stderr.
TEST(ReproduceQuiet, PrintsNoProgress) {
  const fs::path dir = fs::temp_directory_path() / ("scalcal_reproduce_quiet_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string err = dir.string() + ".err";
  const std::string cmd =
      std::string(SCALCAL_CLI) + " reproduce --quick --quiet --out " + dir.string() + " > /dev/null 2> " + err;
  EXPECT_EQ(std::system(cmd.c_str()), 0) << slurp(err);
  EXPECT_EQ(slurp(err), "");
  EXPECT_TRUE(fs::exists(dir / "REPORT.md"));
  fs::remove_all(dir);
  fs::remove(err);
}

}  // namespace
