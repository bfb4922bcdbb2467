// The strict CSV reader every file of scalcal goes through (csv_table.hpp).
#include "numeric/io/csv_table.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
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

std::vector<std::string> split(const std::string& line, bool whitespace) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  if (whitespace) {
    while (in >> field) fields.push_back(field);
    return fields;
  }
  while (std::getline(in, field, ',')) fields.push_back(trim(field));
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
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
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return static_cast<int>(i);
  return -1;
}

CsvTable parse_csv(const std::string& input, const std::string& name) { return parse_table(input, name, {}); }

CsvTable parse_table(const std::string& input, const std::string& name, const TableFormat& format) {
  using L = CsvLimits;
  if (input.size() > L::max_file_bytes)
    throw InputError(name, 0, "file larger than the limit of " + std::to_string(L::max_file_bytes >> 20) + " MiB");
  if (looks_binary(input)) throw InputError(name, 0, binary_reason(input));
  const std::string text = normalise(input);
  CsvTable table;
  table.file = name;
  std::istringstream in(text);
  std::string raw;
  int line_no = 0;
  bool header_seen = !format.columns.empty();
  table.columns = format.columns;
  while (std::getline(in, raw)) {
    ++line_no;
    if (raw.size() > L::max_line_chars)
      throw InputError(name, line_no,
                       "line longer than the limit of " + std::to_string(L::max_line_chars) + " characters");
    std::string line = raw;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    line = trim(line);
    if (line.empty()) continue;
    auto fields = split(line, format.whitespace);
    if (fields.size() > L::max_columns)
      throw InputError(
          name, line_no,
          std::to_string(fields.size()) + " columns, more than the limit of " + std::to_string(L::max_columns));
    if (!header_seen) {
      double probe;
      if (parse_number(fields.front(), probe))
        throw InputError(name, line_no, "expected a header line naming the columns, found numbers");
      for (auto& f : fields) {
        if (f.empty()) throw InputError(name, line_no, "empty column name in the header");
        if (table.column(f) >= 0) throw InputError(name, line_no, "column " + in_quotes(f) + " appears twice");
        table.columns.push_back(f);
      }
      header_seen = true;
      continue;
    }
    if (fields.size() != table.columns.size())
      throw InputError(
          name, line_no,
          "expected " + std::to_string(table.columns.size()) + " values, found " + std::to_string(fields.size()));
    if (table.rows.size() == L::max_rows)
      throw InputError(name, line_no, "more than the limit of " + std::to_string(L::max_rows) + " data rows");
    CsvTable::Row row;
    row.line = line_no;
    for (std::size_t c = 0; c < fields.size(); ++c) {
      double v;
      if (!parse_number(fields[c], v))
        throw InputError(name, line_no, in_quotes(fields[c]) + " in column " + table.columns[c] + " is not a number");
      if (!std::isfinite(v) && !format.nonfinite_allowed)
        throw InputError(name, line_no,
                         "value in column " + table.columns[c] + " is not finite (" + display_name(fields[c]) + ")");
      row.values.push_back(v);
    }
    table.rows.push_back(std::move(row));
  }
  if (!header_seen) throw InputError(name, 0, "empty file: no header line and no data");
  if (!format.columns.empty() && table.rows.empty()) throw InputError(name, 0, "empty file: no data");
  return table;
}

namespace {

// A named pipe with no writer blocks open() and read() forever; it is opened without blocking and
// given kPipeWaitSeconds to deliver its first byte (or its end). Process substitution, <(...),
// and `... | scalcal evaluate /dev/stdin` have a writer and deliver at once.
constexpr int kPipeWaitSeconds = 10;

class InputFile {
 public:
  explicit InputFile(const std::string& path) : path_(path) {
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
  ~InputFile() { ::close(fd_); }

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
};

}  // namespace

CsvTable read_csv(const std::string& path) { return read_table(path, {}); }

// Reads at most the size limit plus one byte, so a device or pipe that never ends (/dev/zero,
// /dev/urandom) or a huge file costs no more than the limit; a directory is refused by name.

CsvTable read_table(const std::string& path, const TableFormat& format) {
  return parse_table(read_text_file(path), path, format);
}

std::string read_text_file(const std::string& path) {
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

}  // namespace scalcal
