// The values a user gave a command, as checked text by option name (the CLI's arguments, or the
// Python keywords turned into the same text), read back typed with the table's defaults. A front end
// that holds data rather than a file name (Python's arrays) passes it beside the text.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "commands/core/json.hpp"
#include "commands/core/option_table.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::commands {

class Values {
 public:
  explicit Values(const CommandTable& table) : table_(&table) {}

  // Checks `text` against the option (Option::check) and stores it; throws UsageError naming the
  // option ("--positions: must be an integer in 3..1000, got '9abc'"). Repeated options append.
  void set(const std::string& option, std::string text);
  void set_flag(const std::string& option, bool on);

  bool given(const std::string& option) const;        // set by the user (not a default)
  std::string text(const std::string& option) const;  // the value, the default, or ""
  long long integer(const std::string& option) const;
  double number(const std::string& option) const;
  bool flag(const std::string& option) const;
  std::vector<std::string> list(const std::string& option) const;

  // Positions given as data (Python: an (N, 3) array) for a PROGRAM argument.
  std::optional<Program> program;
  // A data file's columns given as data (Python: a mapping name -> array), by option name.
  std::map<std::string, CsvTable> tables;
  // A JSON file's object given as data (Python: a dict), by option name.
  std::map<std::string, Json> documents;

  const CommandTable& table() const { return *table_; }

 private:
  const Option& option(const std::string& name) const;
  const CommandTable* table_;
  std::map<std::string, std::vector<std::string>> given_;
};

// Throws UsageError when two options that write files (Option::writes_file) name the same file: by
// the same text, or by two paths to one file ("out.csv" and "./out.csv", a link), e.g.
// `simulate --log X --truth X`. Standard output ("-") is checked by the front end that routes it.
void check_distinct_outputs(const Values& values);

}  // namespace scalcal::commands
