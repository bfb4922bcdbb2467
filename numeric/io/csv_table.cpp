#include "numeric/io/csv_table.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "numeric/io/input_error.hpp"

namespace scalcal {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(trim(field));
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

bool parse_number(const std::string& s, double& out) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && errno != ERANGE;
}

bool looks_binary(const std::string& text) {
  if (text.find('\0') != std::string::npos) return true;
  int control = 0;
  for (unsigned char c : text)
    if (c < 0x20 && c != '\n' && c != '\r' && c != '\t') ++control;
  return control > 0;
}

}  // namespace

int CsvTable::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return static_cast<int>(i);
  return -1;
}

CsvTable parse_csv(const std::string& text, const std::string& name) {
  if (looks_binary(text)) throw InputError(name, 0, "not a text file (binary or control characters)");
  CsvTable table;
  table.file = name;
  std::istringstream in(text);
  std::string raw;
  int line_no = 0;
  bool header_seen = false;
  while (std::getline(in, raw)) {
    ++line_no;
    std::string line = raw;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    line = trim(line);
    if (line.empty()) continue;
    auto fields = split(line);
    if (!header_seen) {
      double probe;
      if (parse_number(fields.front(), probe))
        throw InputError(name, line_no, "expected a header line naming the columns, found numbers");
      for (auto& f : fields) {
        if (f.empty()) throw InputError(name, line_no, "empty column name in the header");
        if (table.column(f) >= 0) throw InputError(name, line_no, "column '" + f + "' appears twice");
        table.columns.push_back(f);
      }
      header_seen = true;
      continue;
    }
    if (fields.size() != table.columns.size())
      throw InputError(name, line_no, "expected " + std::to_string(table.columns.size()) +
                                          " values, found " + std::to_string(fields.size()));
    CsvTable::Row row;
    row.line = line_no;
    for (std::size_t c = 0; c < fields.size(); ++c) {
      double v;
      if (!parse_number(fields[c], v))
        throw InputError(name, line_no, "'" + fields[c] + "' in column " + table.columns[c] + " is not a number");
      if (!std::isfinite(v))
        throw InputError(name, line_no, "value in column " + table.columns[c] + " is not finite (" + fields[c] + ")");
      row.values.push_back(v);
    }
    table.rows.push_back(std::move(row));
  }
  if (!header_seen) throw InputError(name, 0, "empty file: no header line and no data");
  return table;
}

CsvTable read_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot open file: ") + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw InputError(path, 0, "read error");
  return parse_csv(buffer.str(), path);
}

}  // namespace scalcal
