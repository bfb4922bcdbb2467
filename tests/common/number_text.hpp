// Checks on the numbers the CLI prints: every number token of a JSON or CSV text must be the
// shortest decimal that reads back to the same double (std::to_chars gives that independently).
#pragma once
#include <charconv>
#include <regex>
#include <string>
#include <vector>

namespace scalcal::testing {

// Significant digits of a decimal token ("-0.00125e3" has 3).
inline int significant_digits(const std::string& token) {
  std::string mantissa = token.substr(0, token.find_first_of("eE"));
  std::string digits;
  for (char c : mantissa)
    if (c >= '0' && c <= '9') digits += c;
  const auto first = digits.find_first_not_of('0');
  if (first == std::string::npos) return 1;
  digits = digits.substr(first);
  // Trailing zeros of an integer-valued token ("17006112.0", "1500") carry no information.
  while (digits.size() > 1 && digits.back() == '0') digits.pop_back();
  return static_cast<int>(digits.size());
}

inline int shortest_digits(double x) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return significant_digits(std::string(buf, r.ptr));
}

// The number tokens of `text` written with more digits than their shortest round-trip form.
inline std::vector<std::string> overlong_numbers(const std::string& text) {
  std::vector<std::string> bad;
  static const std::regex number(R"((^|[\s,\[:;"])(-?[0-9]+\.?[0-9]*([eE][-+]?[0-9]+)?)(?=$|[\s,\]}\n;"]))");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it) {
    const std::string t = (*it)[2];
    if (significant_digits(t) > shortest_digits(std::stod(t))) bad.push_back(t);
  }
  return bad;
}

}  // namespace scalcal::testing
