// REPORT.md, section by section (report.hpp).
#include "experiments/reproduce/report.hpp"

#include <fstream>
#include <stdexcept>

namespace scalcal::reproduce {

std::string markdown_table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::ostringstream out;
  auto line = [&](const std::vector<std::string>& cells) {
    out << "|";
    for (const auto& c : cells) out << " " << c << " |";
    out << "\n";
  };
  line(header);
  out << "|";
  for (std::size_t i = 0; i < header.size(); ++i) out << (i == 0 ? " --- |" : " ---: |");
  out << "\n";
  for (const auto& r : rows) line(r);
  return out.str();
}

void Report::heading(int level, const std::string& text) {
  body_ << "\n" << std::string(static_cast<std::size_t>(level), '#') << " " << text << "\n\n";
}

void Report::paragraph(const std::string& text) { body_ << text << "\n\n"; }

void Report::figure(const std::string& stem, const std::string& caption) {
  body_ << "![" << caption << "](" << stem << ".png)\n\n*" << caption << "* (for print: [" << stem << ".pdf](" << stem
        << ".pdf); vector: [" << stem << ".svg](" << stem << ".svg); script: [" << stem << ".gp](" << stem
        << ".gp))\n\n";
}

void Report::table(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  body_ << markdown_table(header, rows) << "\n";
}

void Report::missing(const std::string& what) { body_ << "> **MISSING:** " << what << "\n\n"; }

void Report::claim(const std::string& what, const std::string& paper, const std::string& ours,
                   const std::string& diff) {
  claims_.push_back({what, paper, ours, diff});
}

void Report::write(const std::filesystem::path& file, const std::string& preamble, const std::string& epilogue) const {
  std::ofstream out(file);
  out << preamble;
  if (!claims_.empty()) {
    out << "\n## The paper's stated numbers beside scalcal's\n\n"
        << markdown_table({"claim (paper)", "paper", "scalcal", "difference (scalcal − paper, or − the closed form)"},
                          claims_)
        << "\n";
  }
  out << body_.str() << epilogue;
  out.close();  // a full disk shows only when the buffer reaches it
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace scalcal::reproduce
