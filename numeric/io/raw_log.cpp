#include "numeric/io/raw_log.hpp"

#include <cmath>
#include <sstream>

#include "numeric/io/input_error.hpp"

namespace scalcal {
bool looks_like_text_log(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    const char c = line[first];
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
  }
  return false;
}

bool RawLog::finite(int i) const {
  const auto k = static_cast<std::size_t>(i);
  return std::isfinite(t[k]) && std::isfinite(samples[k](0)) && std::isfinite(samples[k](1)) && std::isfinite(samples[k](2));
}

bool is_raw_log(const CsvTable& table) { return table.has("t") && !table.has("position"); }

RawLog raw_log_from_table(const CsvTable& table) {
  for (const char* c : {"t", "ix", "iy", "iz"})
    if (!table.has(c)) throw InputError(table.file, 1, std::string("missing column '") + c + "' (a raw log needs t,ix,iy,iz)");
  const int ct = table.column("t"), ix = table.column("ix"), iy = table.column("iy"), iz = table.column("iz");
  RawLog log;
  log.file = table.file;
  double last = -INFINITY;
  int last_line = 0, finite_rows = 0;
  for (const auto& row : table.rows) {
    const auto& v = row.values;
    log.t.push_back(v[static_cast<std::size_t>(ct)]);
    log.samples.emplace_back(v[static_cast<std::size_t>(ix)], v[static_cast<std::size_t>(iy)], v[static_cast<std::size_t>(iz)]);
    log.lines.push_back(row.line);
    if (!log.finite(log.size() - 1)) continue;
    const double t = log.t.back();
    if (!(t > last))
      throw InputError(table.file, row.line,
                       "time " + std::to_string(t) + " s does not increase (line " + std::to_string(last_line) + " has " +
                           std::to_string(last) + " s)");
    last = t;
    last_line = row.line;
    ++finite_rows;
  }
  if (finite_rows < 2) throw InputError(table.file, 0, "fewer than two rows with finite t, ix, iy, iz");
  return log;
}

RawLog read_raw_log(const std::string& path, LogFormat format) { return parse_raw_log(read_text_file(path), path, format); }

RawLog parse_raw_log(std::string text, const std::string& path, LogFormat format) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  if (format == LogFormat::automatic) format = looks_like_text_log(text) ? LogFormat::text : LogFormat::csv;
  TableFormat f;
  f.nonfinite_allowed = true;
  if (format == LogFormat::text) {
    f.whitespace = true;
    f.columns = {"t", "ix", "iy", "iz"};
  }
  return raw_log_from_table(parse_table(text, path, f));
}

}  // namespace scalcal
