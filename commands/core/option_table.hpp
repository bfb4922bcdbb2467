// Every option of a command, written once: the CLI builds its parser, usage line and --help from the
// table, the Python module its keyword arguments and docstrings, and both check each value with the
// same strict reading (a decimal integer or a finite number within its range, a non-empty text, one
// of its choices). So the two front ends cannot drift apart.
#pragma once
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace scalcal::commands {

enum class OptionKind {
  positional,  // a required argument (PROGRAM)
  integer,     // a decimal integer within [lo, hi]
  number,      // a finite number within [low, high], or positive
  text,        // a non-empty text (a file path, a spec); `why_bad` may refuse more
  choice,      // one of `choices`
  flag,        // on or off
  repeated,    // a text given any number of times (--region A --region B)
};

inline constexpr const char* kRequired = "none, required";

struct Option {
  std::string name;  // "--positions", or for a positional "PROGRAM"
  OptionKind kind = OptionKind::text;
  std::string value_name;  // shown in usage lines: N, FILE, SPEC (integer: INT, number: NUM by default)
  std::string what;        // what it sets, one line
  std::string unit = "none";
  std::string fallback;       // the default as the user would write it ("" : none); kRequired: required
  std::string fallback_text;  // how --help shows the default when it is not a value ("0 = all cores")
  long long lo = 0, hi = 0;   // integer
  double low = -std::numeric_limits<double>::max(), high = std::numeric_limits<double>::max();
  bool positive = false;  // number: x > 0
  std::vector<std::string> choices;
  std::function<std::string(const std::string&)> why_bad;  // text: the reason to refuse it, or ""
  bool cli_only = false;         // how the CLI presents a result (--json, --out): not a Python argument
  bool takes_positions = false;  // a program: Python may also give an (N, 3) array of directions
  bool takes_columns = false;    // a data file: Python may also give its columns (a mapping name -> array)
  bool takes_document = false;   // a JSON file: Python may also give the object itself (a dict)
  bool writes_file = false;      // a file the CLI writes; "-" is standard output

  bool required() const { return kind == OptionKind::positional || fallback == kRequired; }
  // The Python keyword: "--threshold-factor" -> "threshold_factor", "PROGRAM" -> "program", "--from" -> "from_".
  std::string python_name() const;
  // "what (unit: U; default: V)"
  std::string help() const;
  // "" when `text` is a valid value, else the reason ("must be an integer in 3..1000, got '9abc'").
  // Integers and numbers are rewritten in their canonical text.
  std::string check(std::string& text) const;
};

struct CommandTable {
  std::string name;     // "evaluate"
  std::string summary;  // one line for `scalcal help`
  int order = 100;      // position in `scalcal help`
  std::vector<Option> options;

  // "evaluate PROGRAM [--model NAME] [--region SPEC]... [--out FILE] [--json]"
  std::string usage() const;
  const Option* find(const std::string& name) const;  // by CLI or Python name; nullptr if none
};

// Whole-text reads: the text must be all number.
bool read_integer(const std::string& text, long long& x);
bool read_number(const std::string& text, double& x);

}  // namespace scalcal::commands
