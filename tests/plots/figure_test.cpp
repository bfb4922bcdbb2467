// plots::render draws one figure at its print size in three formats: the PDF measures the stated
// width and height in points, the PNG the same at 300 pixels per inch, the SVG at 96; the script
// states the intended width; text that would print below 7 pt is refused.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>

#include "plots/figure.hpp"

namespace fs = std::filesystem;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::uint32_t big_endian(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(s[at + i]);
  return v;
}

class FigureRender : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("scalcal_figure_test_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "line.csv") << "x,y\n0,0\n1,1\n2,4\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  static scalcal::plots::FigureSpec spec() {
    scalcal::plots::FigureSpec s;
    s.name = "line";
    s.comment = "a test line";
    s.width_cm = scalcal::plots::kColumnWidthCm;  // 8.5 cm
    s.height_cm = 6.5;
    s.body =
        "set xlabel 'x" + scalcal::plots::sub("1") + "'\nplot 'line.csv' skip 1 using 1:2 with linespoints title 'y'\n";
    return s;
  }
  fs::path dir_;
};

TEST_F(FigureRender, WritesPdfPngSvgAndScriptAtThePrintSize) {
  const auto out = scalcal::plots::render(dir_, spec());
  EXPECT_EQ(out.pdf, dir_ / "line.pdf");

  const std::string pdf = slurp(out.pdf);
  ASSERT_GT(pdf.size(), 500u);
  EXPECT_EQ(pdf.substr(0, 5), "%PDF-");
  // 8.5 cm x 6.5 cm in PostScript points: 240.94 x 184.25, which cairo writes as whole points.
  std::smatch box;
  ASSERT_TRUE(std::regex_search(pdf, box, std::regex(R"(/MediaBox \[\s*0 0 ([0-9.]+) ([0-9.]+)\s*\])")));
  EXPECT_NEAR(std::stod(box[1]), 8.5 / 2.54 * 72, 1.0);
  EXPECT_NEAR(std::stod(box[2]), 6.5 / 2.54 * 72, 1.0);

  const std::string png = slurp(out.png);
  ASSERT_GT(png.size(), 24u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(big_endian(png, 16), std::lround(8.5 / 2.54 * 300));  // IHDR width, 1004
  EXPECT_EQ(big_endian(png, 20), std::lround(6.5 / 2.54 * 300));  // IHDR height, 768

  const std::string svg = slurp(out.svg);
  EXPECT_NE(svg.find("width=\"321\" height=\"246\""), std::string::npos);  // 96 CSS pixels per inch

  const std::string gp = slurp(out.script);
  EXPECT_NE(gp.find("# intended print width: 85 mm (one journal column)"), std::string::npos) << gp;
  EXPECT_NE(gp.find("text 8 pt there"), std::string::npos);
  for (const char* terminal : {"set terminal pdfcairo", "set terminal pngcairo", "set terminal svg"})
    EXPECT_NE(gp.find(terminal), std::string::npos) << terminal;
}

// pdfcairo's default fontscale 0.5 would print 'Sans,8' as 4 pt (and cairo renders a nominal size at
// 96/72 of it): the script must set the scale that prints 8 pt as 8 pt.
TEST_F(FigureRender, PdfTextIsTheStatedSize) {
  const std::string gp = scalcal::plots::figure_script(spec());
  EXPECT_NE(gp.find("font 'Sans,8' fontscale 0.75"), std::string::npos) << gp;
  EXPECT_NE(gp.find("font 'Sans,25'"), std::string::npos) << gp;  // PNG: 8 pt * 300 / 96
}

TEST_F(FigureRender, WiderFiguresSayTwoColumns) {
  auto s = spec();
  s.width_cm = scalcal::plots::kPageWidthCm;
  EXPECT_NE(scalcal::plots::figure_script(s).find("# intended print width: 175 mm (two journal columns)"),
            std::string::npos);
}

TEST_F(FigureRender, RefusesTextBelowSevenPoints) {
  auto s = spec();
  s.font_pt = 7;  // its indices would print at 6.2 pt
  EXPECT_THROW(scalcal::plots::render(dir_, s), std::invalid_argument);
}

TEST(FigureText, IndicesStayAtSevenPoints) {
  EXPECT_EQ(scalcal::plots::sub("bias"), "_{/*1.1 bias}");
  EXPECT_EQ(scalcal::plots::sup("9"), "^{/*1.1 9}");
  EXPECT_GE(8 * scalcal::plots::kIndexScale, scalcal::plots::kMinTextPt);
}

}  // namespace
