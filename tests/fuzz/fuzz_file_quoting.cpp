// libFuzzer target (issue 50): the quoting of text that scalcal writes into files another reader
// interprets. The first byte picks the writer, the rest is the text:
//   0: plots::gp_quote, a gnuplot string literal. The literal must be one double-quoted string with
//      no byte gnuplot's scanner acts on (an unescaped quote, a backtick, '@', '$', a control or
//      stray byte), and decoded by gnuplot's own escape rules (\ooo: three octal digits after 1-3;
//      \0 and up to three more) it must give back the text exactly. A NUL byte must be refused.
//   1: region_line, a program file's `# region:` line of ';'-separated specs (the text's parts
//      between 0x1E bytes, line breaks and all): read back by program_region, it must give the same specs.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "numeric/io/input_error.hpp"
#include "numeric/program/program_csv.hpp"
#include "plots/figure.hpp"

namespace {

bool octal(char c) { return c >= '0' && c <= '7'; }

// gnuplot 5.4's reading of a double-quoted string (scanner.c, then parse_esc in util.c), or abort.
std::string gnuplot_reads(const std::string& q) {
  if (q.size() < 2 || q.front() != '"' || q.back() != '"') std::abort();
  std::string out;
  for (std::size_t i = 1; i + 1 < q.size(); ++i) {
    const auto c = static_cast<unsigned char>(q[i]);
    if (c == '"' || c == '`' || c == '@' || c == '$' || c < 0x20 || c == 0x7f) std::abort();
    if (c != '\\') {
      out += q[i];
      continue;
    }
    if (i + 2 >= q.size() || !octal(q[i + 1])) std::abort();  // only octal escapes are written
    int value = 0, digits = 0;
    std::size_t j = i + 1;
    const int most = q[j] == '0' ? 4 : 3;  // "\0" takes up to three more digits
    while (digits < most && j + 1 < q.size() && octal(q[j])) value = 8 * value + (q[j++] - '0'), ++digits;
    if (value == 0 || value > 255) std::abort();
    out += static_cast<char>(value);
    i = j - 1;
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || size > 4096) return 0;
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (data[0] % 2 == 0) {
    std::string q;
    try {
      q = scalcal::plots::gp_quote(text);
    } catch (const std::invalid_argument&) {
      if (text.find('\0') == std::string::npos) std::abort();  // only a NUL is refused
      return 0;
    }
    if (text.find('\0') != std::string::npos || gnuplot_reads(q) != text) std::abort();
    return 0;
  }
  std::vector<std::string> specs;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line, '\x1e');) {
    if (line.empty()) continue;  // an empty spec is no spec
    specs.push_back(line);
  }
  if (specs.empty()) return 0;
  const std::string line = scalcal::region_line(specs);
  if (line.find('\n') != line.size() - 1) std::abort();  // one line
  try {
    if (scalcal::program_region(line + "x,y,z\n").specs != specs) std::abort();
  } catch (const scalcal::InputError&) {
    std::abort();  // what region_line writes always reads back
  }
  return 0;
}
