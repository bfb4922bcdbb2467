// The strict CSV reader every file of scalcal goes through (csv_table.hpp).
#include "numeric/io/csv_table.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <optional>
#include <sstream>
#include <string_view>

#include "numeric/io/input_error.hpp"

namespace scalcal {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split_whitespace(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (in >> field) fields.push_back(field);
  return fields;
}

// One line's fields under RFC 4180 (a quoted field may hold the separator, '#' and "" for a quote;
// spaces around a field are dropped); '#' outside quotes starts a comment. A field cannot span
// lines. Returns the reason when the line is malformed, else "" (and `fields` empty for a line
// with nothing but a comment or blanks).
std::string split_csv(const std::string& line, char separator, std::vector<std::string>& fields) {
  fields.clear();
  const auto blank = [](char c) { return c == ' ' || c == '\t'; };
  const std::size_t n = line.size();
  std::size_t i = 0;
  while (i < n && blank(line[i])) ++i;
  if (i == n || line[i] == '#') return "";
  for (;;) {
    while (i < n && blank(line[i])) ++i;
    std::string field;
    if (i < n && line[i] == '"') {
      for (++i;; ++i) {
        if (i == n) return "a quoted field is not closed on its line (fields spanning lines are not read)";
        if (line[i] == '"') {
          if (i + 1 < n && line[i + 1] == '"') {
            field.push_back('"');
            ++i;
          } else {
            break;
          }
        } else {
          field.push_back(line[i]);
        }
      }
      ++i;
      while (i < n && blank(line[i])) ++i;
      if (i < n && line[i] != separator && line[i] != '#') return "text after the closing quote of a field";
    } else {
      while (i < n && line[i] != separator && line[i] != '#') {
        if (line[i] == '"') return "a quote inside an unquoted field (quote the whole field, doubling inner quotes)";
        field.push_back(line[i++]);
      }
      field = trim(field);
    }
    fields.push_back(std::move(field));
    if (i == n || line[i] == '#') return "";
    ++i;  // the separator; one at the end of the line leaves an empty last field
  }
}

// The separator a header line uses: ';' when it has ';' and no ',' outside quotes, else ','.
char header_separator(const std::string& line) {
  bool quoted = false, comma = false, semicolon = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == '#') break;
    comma = comma || c == ',';
    semicolon = semicolon || c == ';';
  }
  return semicolon && !comma ? ';' : ',';
}

bool parse_number(const std::string& s, double& out) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  // ERANGE is both overflow (refused: 1e400 is not a double) and underflow, whose result is the
  // correctly rounded subnormal or zero (kept: a program scaled by 2^-1060 is still a program).
  const bool overflow = errno == ERANGE && std::abs(out) > 1.0;
  return end == s.c_str() + s.size() && !overflow;
}

// A number of a ';'-separated file, where a comma is the decimal comma (0,5): one comma and no
// point is read as a point; "1.000,5" (a thousands separator) is not a number.
bool parse_number(const std::string& s, char separator, double& out) {
  if (separator != ';' || std::count(s.begin(), s.end(), ',') != 1 || s.find('.') != std::string::npos)
    return parse_number(s, out);
  std::string point = s;
  point[point.find(',')] = '.';
  return parse_number(point, out);
}

bool looks_binary(std::string_view text) {
  for (unsigned char c : text)
    if (c < 0x20 && c != '\n' && c != '\r' && c != '\t') return true;
  return false;
}

// What the text is, when it is not text scalcal reads: UTF-16 (a spreadsheet's "Unicode text")
// gets its own advice.
std::string binary_reason(std::string_view text) {
  if (text.starts_with("\xFF\xFE") || text.starts_with("\xFE\xFF")) return "UTF-16 text; save the file as UTF-8 CSV";
  return "not a text file (binary or control characters)";
}

// Strips a UTF-8 byte-order mark and turns CRLF and lone CR line endings into LF.
std::string normalise(std::string text) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  if (text.find('\r') == std::string::npos) return text;
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\r') {
      out.push_back(text[i]);
    } else {
      out.push_back('\n');
      if (i + 1 < text.size() && text[i + 1] == '\n') ++i;
    }
  }
  return out;
}

std::string in_quotes(const std::string& field) { return "'" + display_name(field) + "'"; }

}  // namespace

int CsvTable::column(const std::string& name) const {
  const auto same = [](const std::string& a, const std::string& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char p, char q) {
             return std::tolower(static_cast<unsigned char>(p)) == std::tolower(static_cast<unsigned char>(q));
           });
  };
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (same(columns[i], name)) return static_cast<int>(i);
  return -1;
}

CsvTable parse_csv(const std::string& input, const std::string& name) { return parse_table(input, name, {}); }

namespace {

// The reader's state between lines: the table so far and the separator its header chose.
struct TableReader {
  CsvTable table;
  const TableFormat& format;
  char separator = ',';
  int label = -1;  // the label column's index, -1 when there is none
  bool header_seen = false;

  void header(std::vector<std::string>& fields, int line_no) {
    double probe;
    if (parse_number(fields.front(), probe))
      throw InputError(table.file, line_no, "expected a header line naming the columns, found numbers");
    for (auto& f : fields) {
      if (f.empty()) throw InputError(table.file, line_no, "empty column name in the header");
      if (table.column(f) >= 0) throw InputError(table.file, line_no, "column " + in_quotes(f) + " appears twice");
      table.columns.push_back(f);
    }
    header_seen = true;
  }

  // What the separator explains about a field that is not a number, or "".
  std::string separator_hint(const std::string& field) const {
    if (separator == ',' && field.find(';') != std::string::npos)
      return " (the header separates columns with ',', this line with ';')";
    if (separator == ';' && field.find(',') != std::string::npos)
      return " (a ';'-separated file takes a decimal comma, as in 0,5, but no thousands separator)";
    return "";
  }

  void row(const std::vector<std::string>& fields, int line_no) {
    using L = CsvLimits;
    if (fields.size() != table.columns.size()) {
      std::string hint;
      for (const auto& f : fields)
        if (hint.empty()) hint = separator_hint(f);
      throw InputError(table.file, line_no,
                       "expected " + std::to_string(table.columns.size()) + " values, found " +
                           std::to_string(fields.size()) + hint);
    }
    if (table.rows.size() == L::max_rows)
      throw InputError(table.file, line_no, "more than the limit of " + std::to_string(L::max_rows) + " data rows");
    CsvTable::Row row;
    row.line = line_no;
    for (std::size_t c = 0; c < fields.size(); ++c) {
      double v;
      const bool number = parse_number(fields[c], separator, v);
      if (static_cast<int>(c) == label) {
        if (fields[c].empty()) throw InputError(table.file, line_no, "empty value in column " + table.columns[c]);
        table.labels.push_back(fields[c]);
        if (!number) v = std::nan("");  // a label such as P1
      } else if (!number) {
        throw InputError(
            table.file, line_no,
            in_quotes(fields[c]) + " in column " + table.columns[c] + " is not a number" + separator_hint(fields[c]));
      }
      if (number && !std::isfinite(v) && !format.nonfinite_allowed)
        throw InputError(table.file, line_no,
                         "value in column " + table.columns[c] + " is not finite (" + display_name(fields[c]) + ")");
      row.values.push_back(v);
    }
    table.rows.push_back(std::move(row));
  }
};

}  // namespace

CsvTable parse_table(const std::string& input, const std::string& name, const TableFormat& format) {
  using L = CsvLimits;
  if (input.size() > L::max_file_bytes)
    throw InputError(name, 0, "file larger than the limit of " + std::to_string(L::max_file_bytes >> 20) + " MiB");
  if (looks_binary(input)) throw InputError(name, 0, binary_reason(input));
  const std::string text = normalise(input);
  TableReader r{CsvTable{}, format};
  r.table.file = name;
  r.table.columns = format.columns;
  r.header_seen = !format.columns.empty();
  if (r.header_seen) r.label = r.table.column(kLabelColumn);
  std::istringstream in(text);
  std::string raw;
  std::vector<std::string> fields;
  int line_no = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    if (raw.size() > L::max_line_chars)
      throw InputError(name, line_no,
                       "line longer than the limit of " + std::to_string(L::max_line_chars) + " characters");
    if (format.whitespace) {
      if (const auto hash = raw.find('#'); hash != std::string::npos) raw.erase(hash);
      fields = split_whitespace(raw);
    } else {
      if (!r.header_seen) r.separator = header_separator(raw);
      if (const std::string why = split_csv(raw, r.separator, fields); !why.empty())
        throw InputError(name, line_no, why);
    }
    if (fields.empty()) continue;
    if (fields.size() > L::max_columns)
      throw InputError(
          name, line_no,
          std::to_string(fields.size()) + " columns, more than the limit of " + std::to_string(L::max_columns));
    if (!r.header_seen) {
      r.header(fields, line_no);
      r.label = r.table.column(kLabelColumn);
      continue;
    }
    r.row(fields, line_no);
  }
  if (!r.header_seen) throw InputError(name, 0, "empty file: no header line and no data");
  if (!format.columns.empty() && r.table.rows.empty()) throw InputError(name, 0, "empty file: no data");
  return std::move(r.table);
}

namespace {

// A named pipe with no writer blocks open() and read() forever; it is opened without blocking and
// given kPipeWaitSeconds to deliver its first byte (or its end). Process substitution, <(...),
// and `... | scalcal evaluate /dev/stdin` have a writer and deliver at once.
constexpr int kPipeWaitSeconds = 10;

class InputFile {
 public:
  explicit InputFile(const std::string& path) : path_(path) {
    if (path == "-") {  // standard input: not ours to close
      fd_ = STDIN_FILENO;
      owned_ = false;
      return;
    }
    std::error_code ec;
    const auto status = std::filesystem::status(path, ec);
    if (std::filesystem::is_directory(status)) throw InputError(path, 0, "is a directory, not a CSV file");
    const bool pipe = std::filesystem::is_fifo(status) || std::filesystem::is_socket(status);
    fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (pipe ? O_NONBLOCK : 0));
    if (fd_ < 0) throw InputError(path, 0, std::string("cannot open file: ") + std::strerror(errno));
    if (pipe) {
      pollfd p{fd_, POLLIN, 0};
      int ready;
      do ready = ::poll(&p, 1, kPipeWaitSeconds * 1000);
      while (ready < 0 && errno == EINTR);
      if (ready == 0) {
        ::close(fd_);
        throw InputError(path, 0,
                         "is a named pipe that gave no data within " + std::to_string(kPipeWaitSeconds) +
                             " s (no program is writing to it?)");
      }
      ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
    }
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  ~InputFile() {
    if (owned_) ::close(fd_);
  }

  // Up to `size` bytes; 0 at the end.
  std::size_t read(char* data, std::size_t size) {
    for (;;) {
      const ssize_t n = ::read(fd_, data, size);
      if (n >= 0) return static_cast<std::size_t>(n);
      if (errno != EINTR) throw InputError(path_, 0, std::string("read error: ") + std::strerror(errno));
    }
  }

 private:
  std::string path_;
  int fd_ = -1;
  bool owned_ = true;
};

}  // namespace

CsvTable read_csv(const std::string& path) { return read_table(path, {}); }

// Reads at most the size limit plus one byte, so a device or pipe that never ends (/dev/zero,
// /dev/urandom) or a huge file costs no more than the limit; a directory is refused by name.

CsvTable read_table(const std::string& path, const TableFormat& format) {
  return parse_table(read_text_file(path), path, format);
}

namespace {

std::string read_all(const std::string& path) {
  InputFile in(path);
  constexpr std::size_t limit = CsvLimits::max_file_bytes;
  std::string text;
  std::array<char, 1 << 16> chunk;
  while (text.size() <= limit) {
    const std::size_t got = in.read(chunk.data(), chunk.size());
    if (got == 0) break;
    const std::string_view piece(chunk.data(), got);
    // Binary content is refused as soon as it is seen: /dev/urandom gives no end and no text.
    if (looks_binary(piece)) throw InputError(path, 0, binary_reason(text.empty() ? piece : std::string_view(text)));
    text.append(piece.substr(0, limit + 1 - text.size()));
  }
  return text;
}

}  // namespace

std::string read_text_file(const std::string& path) {
  if (path != "-") return read_all(path);
  // Standard input can be read only once: its text is kept for the process's later reads.
  static std::mutex mutex;
  static std::optional<std::string> standard_input;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!standard_input) standard_input = read_all(path);
  return *standard_input;
}

}  // namespace scalcal
