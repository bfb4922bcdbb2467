// Files as people have them (issue 33): RFC 4180 quoted fields, headers in any case, ';' as the
// separator with decimal commas, and text position labels, each read to the same numbers as the
// plain file; their defects stay one InputError naming the file, the line and the reason.
#include <gtest/gtest.h>

#include <cmath>

#include "numeric/calibration/measurements_csv.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/program_csv.hpp"

namespace scalcal {
namespace {

// The nine axes of the plain file, written by hand in each dialect below.
const char* kPlain = "x,y,z\n1,0,0\n-1,0,0\n0,1,0\n0,-1,0\n0,0,1\n0,0,-1\n1,1,0\n0,1,1\n1,0,1\n";

void expect_same_program(const std::string& text) {
  const Program plain = program_from_table(parse_csv(kPlain, "plain.csv"));
  const Program other = program_from_table(parse_csv(text, "other.csv"));
  ASSERT_EQ(other.size(), plain.size());
  for (int i = 0; i < plain.size(); ++i) EXPECT_EQ(other.positions[i], plain.positions[i]) << "row " << i;
}

void expect_error(const std::string& text, int line, const std::string& fragment) {
  try {
    parse_csv(text, "f.csv");
    FAIL() << "accepted: " << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "f.csv");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(CsvTable, QuotedFieldsReadAsPlain) {
  expect_same_program(
      "\"x\",\"y\",\"z\"\n\"1\",\"0\",\"0\"\n\"-1\", 0 ,0\n0,\"1\",0\n0,-1,0\n0,0,1\n0,0,-1\n1,1,0\n0,1,1\n"
      "\"1\" , \"0\" , \"1\"\n");
}

TEST(CsvTable, QuotedFieldsKeepSeparatorsQuotesAndHashes) {
  const CsvTable t = parse_csv("\"a,b\",\"say \"\"hi\"\"\",\"c#d\",e\n1,2,3,4 # comment\n", "q.csv");
  ASSERT_EQ(t.columns.size(), 4u);
  EXPECT_EQ(t.columns[0], "a,b");
  EXPECT_EQ(t.columns[1], "say \"hi\"");
  EXPECT_EQ(t.columns[2], "c#d");
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.rows[0].values, (std::vector<double>{1, 2, 3, 4}));
}

TEST(CsvTable, HeadersInAnyCase) {
  std::string upper = kPlain;
  upper.replace(0, 5, "X,Y,Z");
  expect_same_program(upper);
  const CsvTable t = parse_csv("Alpha1_Deg,ALPHA2_DEG\n0,0\n", "a.csv");
  EXPECT_EQ(t.column("alpha1_deg"), 0);
  EXPECT_EQ(t.column("alpha2_deg"), 1);
  EXPECT_EQ(t.columns[0], "Alpha1_Deg");  // kept as written, for messages
  expect_error("x,X\n1,2\n", 1, "column 'X' appears twice");
}

TEST(CsvTable, SemicolonsWithDecimalCommas) {
  expect_same_program("x;y;z\n1;0;0\n-1;0;0\n0;1;0\n0;-1;0\n0;0;1\n0;0;-1\n1;1;0\n0;1;1\n1;0;1\n");
  const CsvTable t = parse_csv("a;b;c\n0,5;1,25;-2\n\"3,5\";1e-3;4.5\n", "s.csv");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0].values, (std::vector<double>{0.5, 1.25, -2}));
  EXPECT_EQ(t.rows[1].values, (std::vector<double>{3.5, 0.001, 4.5}));
  expect_error("a;b\n1.000,5;2\n", 2, "decimal comma");
  expect_error("a,b\n0,5;1,2\n", 2, "this line with ';'");
}

TEST(CsvTable, QuotingDefects) {
  expect_error("x,y\n\"1,2\n", 2, "not closed on its line");
  expect_error("x,y\n\"1\"2,3\n", 2, "text after the closing quote");
  expect_error("x,y\n1\"2,3\n", 2, "a quote inside an unquoted field");
  expect_error("\"\",y\n1,2\n", 1, "empty column name");
}

TEST(CsvTable, PositionLabels) {
  const CsvTable t = parse_csv("Position,ix,iy,iz\nP1,1,0,0\n\"P 2\",0,1,0\n3,0,0,1\n", "b.csv");
  ASSERT_EQ(t.labels, (std::vector<std::string>{"P1", "P 2", "3"}));
  EXPECT_TRUE(std::isnan(t.rows[0].values[0]));
  EXPECT_EQ(t.rows[2].values[0], 3.0);
  expect_error("position,ix\n,1\n", 2, "empty value in column position");
  expect_error("ix,iy\nP1,1\n", 2, "'P1' in column ix is not a number");
}

// Labelled positions group as numbered ones: the same samples, positions in order of first
// appearance.
TEST(CsvTable, LabelledPositionsGroupAsNumbered) {
  const std::string numbered = "position,ix,iy,iz\n7,1,0,0\n7,1.1,0,0\n2,0,1,0\n7,0.9,0,0\n2,0,1.1,0\n";
  const std::string labelled = "position,ix,iy,iz\nP7,1,0,0\nP7,1.1,0,0\nP2,0,1,0\nP7,0.9,0,0\nP2,0,1.1,0\n";
  const auto a = measurements_from_table(parse_csv(numbered, "n.csv"), false);
  const auto b = measurements_from_table(parse_csv(labelled, "l.csv"), false);
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(b[k].samples, a[k].samples);
    EXPECT_EQ(b[k].sample_lines, a[k].sample_lines);
  }
  EXPECT_EQ(b[0].samples.size(), 3u);
  EXPECT_EQ(b[1].line, 4);
  try {
    measurements_from_table(parse_csv("position,ix,iy,iz\n1.5,1,0,0\n", "h.csv"), false);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(std::string(e.what()).find("integer or a label"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace scalcal
