// A raw instrument log: time and the three raw outputs, sample by sample (raw_log.hpp).
#include "numeric/calibration/raw_log.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal {
bool looks_like_text_log(const std::string& text) {
  // A byte-order mark is not part of the first line (both readers drop it).
  std::istringstream in(text.rfind("\xEF\xBB\xBF", 0) == 0 ? text.substr(3) : text);
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
  return std::isfinite(t[k]) && std::isfinite(samples[k](0)) && std::isfinite(samples[k](1)) &&
         std::isfinite(samples[k](2));
}

int time_column(const CsvTable& table) {
  for (std::size_t k = 0; k < table.columns.size(); ++k) {
    std::string name = table.columns[k];
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (name == "t" || name == "t_s" || name == "time" || name == "time_s" || name == "timestamp")
      return static_cast<int>(k);
  }
  return -1;
}

bool is_raw_log(const CsvTable& table) { return time_column(table) >= 0 && !table.has("position"); }

RawLog raw_log_from_table(const CsvTable& table, double rate) {
  const int ct = time_column(table);
  if (ct < 0 && !(rate > 0))
    throw InputError(table.file, 1,
                     words("no time column (t, t_s, time, time_s or timestamp): give the sample rate with {rate HZ}"));
  for (const char* c : {"ix", "iy", "iz"})
    if (!table.has(c))
      throw InputError(table.file, 1, std::string("missing column '") + c + "' (a raw log needs ix,iy,iz)");
  const int ix = table.column("ix"), iy = table.column("iy"), iz = table.column("iz");
  RawLog log;
  log.file = table.file;
  double last = -INFINITY;
  int last_line = 0, finite_rows = 0;
  for (const auto& row : table.rows) {
    const auto& v = row.values;
    log.t.push_back(rate > 0 ? static_cast<double>(log.t.size()) / rate : v[static_cast<std::size_t>(ct)]);
    log.samples.emplace_back(v[static_cast<std::size_t>(ix)], v[static_cast<std::size_t>(iy)],
                             v[static_cast<std::size_t>(iz)]);
    log.lines.push_back(row.line);
    if (!log.finite(log.size() - 1)) continue;
    const double t = log.t.back();
    if (!(t > last))
      throw InputError(table.file, row.line,
                       "time " + std::to_string(t) + " s does not increase (line " + std::to_string(last_line) +
                           " has " + std::to_string(last) + " s)");
    last = t;
    last_line = row.line;
    ++finite_rows;
  }
  if (finite_rows < 2) throw InputError(table.file, 0, "fewer than two rows with finite t, ix, iy, iz");
  return log;
}

bool rows_change_like_a_log(const CsvTable& table) {
  if (!table.has("ix") || !table.has("iy") || !table.has("iz") || table.rows.size() < 30) return false;
  const auto at = [&](std::size_t k) {
    const auto& v = table.rows[k].values;
    return Vec3(v[static_cast<std::size_t>(table.column("ix"))], v[static_cast<std::size_t>(table.column("iy"))],
                v[static_cast<std::size_t>(table.column("iz"))]);
  };
  const std::size_t n = table.rows.size(), half = n / 2;
  std::vector<double> step, far;
  for (std::size_t k = 0; k + 1 < n; ++k)
    if (const double d = (at(k + 1) - at(k)).norm(); std::isfinite(d)) step.push_back(d);
  for (std::size_t k = 0; k + half < n; ++k)
    if (const double d = (at(k + half) - at(k)).norm(); std::isfinite(d)) far.push_back(d);
  if (step.empty() || far.empty()) return false;
  const auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  return median(step) < 0.2 * median(far);
}

RawLog read_raw_log(const std::string& path, LogFormat format, double rate) {
  return parse_raw_log(read_text_file(path), path, format, rate);
}

namespace {

// Fields on the first line that is neither blank nor a comment (text logs have no header).
int text_fields(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream fields(line);
    int n = 0;
    for (std::string f; fields >> f;) ++n;
    if (n > 0) return n;
  }
  return 0;
}

}  // namespace

RawLog parse_raw_log(std::string text, const std::string& path, LogFormat format, double rate) {
  if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
  if (format == LogFormat::automatic) format = looks_like_text_log(text) ? LogFormat::text : LogFormat::csv;
  TableFormat f;
  f.nonfinite_allowed = true;
  if (format == LogFormat::text) {
    f.whitespace = true;
    f.columns = {"t", "ix", "iy", "iz"};
    if (rate > 0 && text_fields(text) == 3) f.columns = {"ix", "iy", "iz"};
  }
  return raw_log_from_table(parse_table(text, path, f), rate);
}

}  // namespace scalcal
