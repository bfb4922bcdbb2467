// A strict reader for the numeric CSV files scalcal takes (programs, measurements): a header
// line, then numbers; '#' starts a comment; blank lines are skipped. A UTF-8 byte-order mark and
// CRLF or CR line endings (what spreadsheets export) are accepted. Every defect is an InputError
// naming the file, the line and the reason, and the input limits below are enforced before any
// work grows with the input, so no file makes the reader hang or exhaust memory.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace scalcal {

// Input limits (README, "Input limits"). Far above any real program or bench file (a bench
// file of 100000 positions x 10 samples is ~10^6 rows, ~60 MB), far below what hurts.
struct CsvLimits {
  static constexpr std::size_t max_file_bytes = 64u << 20;  // 64 MiB
  static constexpr std::size_t max_line_chars = 4096;
  static constexpr std::size_t max_columns = 64;
  static constexpr std::size_t max_rows = 1000000;  // data rows, comments and blank lines not counted
};

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
