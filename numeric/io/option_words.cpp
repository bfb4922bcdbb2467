// Options named in the running front end's words (option_words.hpp).
#include "numeric/io/option_words.hpp"

#include <atomic>

namespace scalcal {
namespace {

std::atomic<OptionStyle>& style_slot() {
  static std::atomic<OptionStyle> style{OptionStyle::cli};
  return style;
}

bool name_char(char c, bool first) {
  return (c >= 'a' && c <= 'z') || (!first && ((c >= '0' && c <= '9') || c == '-'));
}

std::string render(std::string_view name, std::string_view value, bool has_value) {
  if (option_style() == OptionStyle::cli)
    return "--" + std::string(name) + (has_value ? " " + std::string(value) : std::string());
  return python_keyword(name) + "=" + std::string(value);
}

}  // namespace

std::string python_keyword(std::string_view name) {
  std::string out;
  for (char c : name) {
    if (c == '-' && out.empty()) continue;  // the leading dashes
    out += c == '-' ? '_' : static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  }
  // A Python keyword takes a trailing underscore, as PEP 8 has it: --from is from_.
  static const char* const keywords[] = {
      "and",      "as",     "assert",  "async", "await", "break",  "class", "continue", "def",  "del",  "elif",
      "else",     "except", "finally", "for",   "from",  "global", "if",    "import",   "in",   "is",   "lambda",
      "nonlocal", "not",    "or",      "pass",  "raise", "return", "try",   "while",    "with", "yield"};
  for (const char* k : keywords)
    if (out == k) return out + "_";
  return out;
}

void set_option_style(OptionStyle style) { style_slot().store(style, std::memory_order_relaxed); }

OptionStyle option_style() { return style_slot().load(std::memory_order_relaxed); }

std::string words(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 16);
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t j = i + 1;
    if (text[i] != '{' || j >= text.size() || !name_char(text[j], true)) {
      out += text[i++];
      continue;
    }
    while (j < text.size() && name_char(text[j], false)) ++j;
    const std::string_view name = text.substr(i + 1, j - i - 1);
    std::size_t close = j;
    if (j < text.size() && text[j] == ' ') close = text.find_first_of("{}", j);
    if (close == std::string_view::npos || close >= text.size() || text[close] != '}' ||
        close == j + 1) {  // not an option: "{" and the text after it stay as they are
      out += text[i++];
      continue;
    }
    const bool has_value = close > j;
    out += render(name, has_value ? text.substr(j + 1, close - j - 1) : std::string_view(), has_value);
    i = close + 1;
    // "... {model} " at the end: the caller appends the value; Python joins it to the "=".
    if (!has_value && option_style() == OptionStyle::python && i + 1 == text.size() && text[i] == ' ') ++i;
  }
  return out;
}

std::string option_word(std::string_view name) {
  while (!name.empty() && name.front() == '-') name.remove_prefix(1);
  return option_style() == OptionStyle::cli ? "--" + std::string(name) : python_keyword(name);
}

}  // namespace scalcal
