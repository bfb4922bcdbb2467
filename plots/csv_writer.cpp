// The CSV file behind a figure (csv_writer.hpp).
#include "plots/csv_writer.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace scalcal::plots {

CsvWriter::CsvWriter(const std::filesystem::path& file, const std::vector<std::string>& header)
    : path_(file), out_(file), columns_(header.size()) {
  if (!out_) throw std::runtime_error("cannot write " + file.string());
  std::vector<std::string> quoted;
  for (const auto& h : header) quoted.push_back(text(h));
  row(quoted);
}

void CsvWriter::row(const std::vector<std::string>& cells) {
  if (cells.size() != columns_)
    throw std::logic_error(path_.string() + ": row of " + std::to_string(cells.size()) + " cells, header has " +
                           std::to_string(columns_));
  for (std::size_t i = 0; i < cells.size(); ++i) out_ << (i ? "," : "") << cells[i];
  out_ << "\n";
  if (!out_) throw std::runtime_error("cannot write " + path_.string());
}

void CsvWriter::close() {
  if (!out_.is_open()) return;
  out_.close();
  if (!out_) throw std::runtime_error("cannot write " + path_.string());
}

std::string CsvWriter::num(double x) {
  if (!std::isfinite(x)) return "";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string CsvWriter::text(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace scalcal::plots
