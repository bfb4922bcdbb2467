// A strict reader for the numeric CSV files scalcal takes (programs, measurements): a header
// line, then numbers; '#' starts a comment; blank lines are skipped. A UTF-8 byte-order mark and
// CRLF or CR line endings (what spreadsheets export) are accepted; so are RFC 4180 quoted fields
// ("1", "a,b", "" for a quote inside, on one line), column names in any case (X = x), and ';' as
// the separator when the header has ';' and no ',' (then a comma in a number is its decimal
// comma, as in 0,5, the only reading such a file allows). Every defect is an InputError
// naming the file, the line and the reason, and the input limits below are enforced before any
// work grows with the input, so no file makes the reader hang or exhaust memory.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace scalcal {

// Input limits (docs/evaluate.md, "Input limits"). Far above any real program or bench file (a bench
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
  std::vector<std::string> columns;  // as the header spells them
  std::vector<Row> rows;
  // The text of the label column (kLabelColumn), row by row, when the table has one: its values
  // may be labels such as P1 (their value is then NaN) as well as numbers. Empty otherwise.
  std::vector<std::string> labels;

  int column(const std::string& name) const;  // index, or -1 when absent; case-insensitive
  bool has(const std::string& name) const { return column(name) >= 0; }
};

// The one column whose values may be text labels (a bench file's positions, P1, P2, ...).
inline constexpr const char* kLabelColumn = "position";

// How a table is written, when it is not scalcal's default CSV (a raw instrument log).
struct TableFormat {
  bool whitespace = false;           // fields separated by runs of spaces or tabs, not commas
  std::vector<std::string> columns;  // the columns' names when the file has no header line
  bool nonfinite_allowed = false;    // NaN and inf are read (a log's dropouts, counted later), not refused
};

// Reads and checks a CSV file; throws InputError on any defect (missing or unreadable file,
// binary content, no header, ragged rows, non-numeric, NaN or infinite values).
CsvTable read_csv(const std::string& path);
// The same under a format, with the same limits and messages.
CsvTable read_table(const std::string& path, const TableFormat& format);

// The file's text, at most the size limit plus one byte (so /dev/zero or a huge file costs no
// more), refused at once when binary; a directory or a named pipe nobody writes to is refused by name.
// "-" is standard input, under the same limits; it is read once per process and the same text is
// returned to every later call (a program's region line and its rows are read from one text).
std::string read_text_file(const std::string& path);

// The same for text already in memory; `name` is used in messages.
CsvTable parse_csv(const std::string& text, const std::string& name);
CsvTable parse_table(const std::string& text, const std::string& name, const TableFormat& format);

}  // namespace scalcal
