// A strict reader for the numeric CSV files scalcal takes (programs, measurements): a header
// line, then numbers; '#' starts a comment; blank lines are skipped. Every defect is an
// InputError naming the file, the line and the reason.
#pragma once
#include <string>
#include <vector>

namespace scalcal {

struct CsvTable {
  struct Row {
    int line = 0;  // 1-based line number in the file
    std::vector<double> values;
  };
  std::string file;
  std::vector<std::string> columns;
  std::vector<Row> rows;

  int column(const std::string& name) const;  // index, or -1 when absent
  bool has(const std::string& name) const { return column(name) >= 0; }
};

// Reads and checks a CSV file; throws InputError on any defect (missing or unreadable file,
// binary content, no header, ragged rows, non-numeric, NaN or infinite values).
CsvTable read_csv(const std::string& path);

// The same for text already in memory; `name` is used in messages.
CsvTable parse_csv(const std::string& text, const std::string& name);

}  // namespace scalcal
