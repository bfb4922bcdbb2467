// REPORT.md of `scalcal reproduce`, built section by section: each figure or table appends its
// heading, its embedded image and its comparison with the paper. The summary of the paper's stated
// numbers is kept apart and written at the top.
#pragma once
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace scalcal::reproduce {

class Report {
 public:
  void heading(int level, const std::string& text);
  void paragraph(const std::string& text);
  void figure(const std::string& stem, const std::string& caption);  // PNG embedded, PDF and SVG linked
  void table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
  void missing(const std::string& what);  // a clearly marked gap, never a made-up number

  // Rows of the "paper vs scalcal" summary: claim, paper's value, scalcal's value, difference.
  void claim(const std::string& what, const std::string& paper, const std::string& ours, const std::string& diff);

  void write(const std::filesystem::path& file, const std::string& preamble, const std::string& epilogue) const;

 private:
  std::ostringstream body_;
  std::vector<std::vector<std::string>> claims_;
};

std::string markdown_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);

}  // namespace scalcal::reproduce
