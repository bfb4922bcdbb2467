// The strict CSV reader: what it accepts, and that every defect names the file, the line and the
// reason.
#include <gtest/gtest.h>

#include <cmath>

#include "numeric/io/input_error.hpp"
#include "numeric/program/program_csv.hpp"

namespace scalcal {
namespace {

std::string nine_axes_rows() { return "1,0,0\n-1,0,0\n0,1,0\n0,-1,0\n0,0,1\n0,0,-1\n1,1,0\n0,1,1\n1,0,1\n"; }

Program parse(const std::string& text) { return program_from_table(parse_csv(text, "prog.csv")); }

void expect_error(const std::string& text, int line, const std::string& fragment) {
  try {
    parse(text);
    FAIL() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "prog.csv");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ProgramCsv, CartesianRowsAreNormalised) {
  const Program p = parse("# a comment\nx,y,z\n" + nine_axes_rows());
  ASSERT_EQ(p.size(), 9);
  EXPECT_NEAR(p.positions[6].norm(), 1.0, 1e-15);
  EXPECT_NEAR(p.positions[6](0), std::sqrt(0.5), 1e-15);
}

TEST(ProgramCsv, AnglesFollowTheTablesConvention) {
  std::string text = "alpha1_deg,alpha2_deg\n90,0   # along y\n0,90\n";
  for (int i = 0; i < 7; ++i) text += std::to_string(40 * i) + "," + std::to_string(10 * i - 30) + "\n";
  const Program p = parse(text);
  EXPECT_NEAR(p.positions[0](1), 1.0, 1e-15);
  EXPECT_NEAR(p.positions[1](2), 1.0, 1e-15);
  const Eigen::Vector2d back = angles_deg(p.positions[6]);  // row i = 4: (160, 10)
  EXPECT_NEAR(back(0), 160.0, 1e-12);
  EXPECT_NEAR(back(1), 10.0, 1e-12);
}

TEST(ProgramCsv, WrittenProgramsReadBack) {
  const Program p = Program::random(11, 4);
  std::ostringstream out;
  write_program_csv(out, p);
  const Program q = parse(out.str());
  ASSERT_EQ(q.size(), 11);
  for (int i = 0; i < 11; ++i) EXPECT_LT((p.positions[i] - q.positions[i]).norm(), 1e-15);
}

TEST(ProgramCsv, Defects) {
  expect_error("", 0, "empty file");
  expect_error("# only a comment\n\n", 0, "empty file");
  expect_error("x,y,z\n", 0, "only 0 positions");
  expect_error("1,0,0\n" + nine_axes_rows(), 1, "header");
  expect_error("a,b,c\n" + nine_axes_rows(), 1, "x,y,z or alpha1_deg,alpha2_deg");
  expect_error("x,y,z\n1,0,0\n0,1\n", 3, "expected 3 values, found 2");
  expect_error("x,y,z\n1,0,0\n0,abc,1\n", 3, "'abc' in column y is not a number");
  expect_error("x,y,z\n1,0,0\nnan,0,1\n", 3, "not finite");
  expect_error("x,y,z\n1,0,0\n0,inf,1\n", 3, "not finite");
  expect_error("x,y,z\n1,0,0\n0,0,0\n" + nine_axes_rows(), 3, "zero vector");
  expect_error("x,y,z\n1,0,0\n0,1,0\n", 0, "only 2 positions");
  expect_error(std::string("x,y,z\n1,0\0,0\n", 14), 0, "not a text file");
}

TEST(ProgramCsv, MissingFile) {
  try {
    read_program_csv("/nonexistent/dir/prog.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/dir/prog.csv");
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos);
  }
}

}  // namespace
}  // namespace scalcal
