// The CSV file behind a figure: a header row, then one row per point. Numbers are written at
// full precision (%.17g) so the CSV reproduces the figure and the report to the last bit; a
// missing value (NaN, or a rank-deficient program's infinity) is an empty cell, which gnuplot
// skips and every CSV reader accepts.
#pragma once
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace scalcal::plots {

class CsvWriter {
 public:
  CsvWriter(const std::filesystem::path& file, const std::vector<std::string>& header);

  // One row; it must have as many cells as the header.
  void row(const std::vector<std::string>& cells);

  // Flushes and closes the file (the destructor does too): call it before gnuplot reads the file.
  void close();

  const std::filesystem::path& path() const { return path_; }

  static std::string num(double x);               // %.17g, empty when not finite
  static std::string text(const std::string& s);  // quoted when it holds a comma or a quote

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  std::size_t columns_;
};

}  // namespace scalcal::plots
