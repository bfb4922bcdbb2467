// Options named in each front end's words (numeric/io/option_words.hpp): the shell's flags, Python's
// keywords; the expected texts written by hand from the two front ends' syntax.
#include "numeric/io/option_words.hpp"

#include <gtest/gtest.h>

namespace scalcal {
namespace {

// Each test leaves the process in the CLI's style, as it found it.
struct Style {
  explicit Style(OptionStyle s) { set_option_style(s); }
  ~Style() { set_option_style(OptionStyle::cli); }
};

TEST(OptionWords, TheShellSaysFlags) {
  Style style(OptionStyle::cli);
  EXPECT_EQ(words("lengthen {still}, shorten {window}"), "lengthen --still, shorten --window");
  EXPECT_EQ(words("give the rate with {rate HZ}"), "give the rate with --rate HZ");
  EXPECT_EQ(words("{temperature T1..T2} (degrees Celsius)"), "--temperature T1..T2 (degrees Celsius)");
  EXPECT_EQ(words("the fit of {model} "), "the fit of --model ");  // the caller appends the value
  EXPECT_EQ(option_word("threshold-factor"), "--threshold-factor");
  EXPECT_EQ(option_word("--region"), "--region");
}

TEST(OptionWords, PythonSaysKeywords) {
  Style style(OptionStyle::python);
  EXPECT_EQ(words("lengthen {still}, shorten {window}"), "lengthen still=, shorten window=");
  EXPECT_EQ(words("{threshold-factor 4} and {from PROGRAM}"), "threshold_factor=4 and from_=PROGRAM");
  EXPECT_EQ(words("the fit of {model} "), "the fit of model=");
  EXPECT_EQ(words("{model} cannot"), "model= cannot");  // a space inside the text stays
  EXPECT_EQ(option_word("--threshold-factor"), "threshold_factor");
  EXPECT_EQ(option_word("from"), "from_");
}

TEST(OptionWords, OtherBracesAreText) {
  for (OptionStyle s : {OptionStyle::cli, OptionStyle::python}) {
    Style style(s);
    for (const char* text : {"{", "}", "{}", "a {\"x\": 1}", "{Upper}", "{9}", "{open", "{a }", "x {"})
      EXPECT_EQ(words(text), text) << text;
  }
}

}  // namespace
}  // namespace scalcal
