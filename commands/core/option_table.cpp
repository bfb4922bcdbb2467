// Option tables (option_table.hpp): help texts, usage lines and the strict reading of values.
#include "commands/core/option_table.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

#include "numeric/io/option_words.hpp"

namespace scalcal::commands {
namespace {

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

// The shortest text that reads back to the same double ("0.5", "1e-09").
std::string shortest(double x) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
  return std::string(buffer, end);
}

std::string range_text(double x) {
  if (x == std::numeric_limits<double>::max()) return "inf";
  if (x == -std::numeric_limits<double>::max()) return "-inf";
  return shortest(x);
}

std::string choice_list(const std::vector<std::string>& choices) {
  std::string list;
  for (std::size_t i = 0; i < choices.size(); ++i)
    list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  return list;
}

}  // namespace

bool read_integer(const std::string& s, long long& x) {
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, x);
  return !s.empty() && ec == std::errc() && ptr == end;
}

bool read_number(const std::string& s, double& x) {
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, x);
  return !s.empty() && ec == std::errc() && ptr == end && std::isfinite(x);
}

std::string Option::python_name() const { return python_keyword(name); }

std::string Option::help() const {
  if (kind == OptionKind::positional || kind == OptionKind::flag) return what;
  if (fallback == kRequired) return what + " (unit: " + unit + "; required)";
  const std::string shown = !fallback_text.empty() ? fallback_text : fallback.empty() ? std::string("none") : fallback;
  return what + " (unit: " + unit + "; default: " + shown + ")";
}

std::string Option::check(std::string& s) const {
  switch (kind) {
    case OptionKind::integer: {
      long long x = 0;
      if (!read_integer(s, x) || x < lo || x > hi)
        return "must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " + in_quotes(s);
      s = std::to_string(x);
      return "";
    }
    case OptionKind::number: {
      double x = 0;
      if (positive) {
        if (!read_number(s, x)) return "must be a positive number, got " + in_quotes(s);
        if (!(x > 0)) return "must be positive, got " + in_quotes(s);
      } else if (!read_number(s, x) || x < low || x > high) {
        return "must be a number in " + range_text(low) + ".." + range_text(high) + ", got " + in_quotes(s);
      }
      s = shortest(x);
      return "";
    }
    case OptionKind::choice:
      for (const auto& c : choices)
        if (s == c) return "";
      return "must be " + choice_list(choices) + ", got " + in_quotes(s);
    case OptionKind::flag:
      return "";
    case OptionKind::positional:
    case OptionKind::text:
    case OptionKind::repeated:
      if (why_bad) return why_bad(s);
      return s.empty() ? "must not be empty" : "";
  }
  return "";
}

std::string CommandTable::usage() const {
  std::string u = name;
  for (const auto& o : options) {
    std::string piece;
    switch (o.kind) {
      case OptionKind::positional:
        piece = o.name;
        break;
      case OptionKind::flag:
        piece = o.name;
        break;
      case OptionKind::choice: {
        std::string names;
        for (const auto& c : o.choices) names += (names.empty() ? "" : "|") + c;
        piece = o.name + " " + (o.value_name.empty() ? names : o.value_name);
        break;
      }
      default:
        if (!o.name.starts_with("-")) {  // an optional positional argument (its name has no dashes)
          piece = o.name;
          break;
        }
        piece = o.name + " " +
                (o.value_name.empty() ? (o.kind == OptionKind::integer  ? "INT"
                                         : o.kind == OptionKind::number ? "NUM"
                                                                        : "TEXT")
                                      : o.value_name);
    }
    if (o.kind == OptionKind::repeated)
      piece = "[" + piece + "]...";
    else if (!o.required())
      piece = "[" + piece + "]";
    u += " " + piece;
  }
  return u;
}

const Option* CommandTable::find(const std::string& n) const {
  for (const auto& o : options)
    if (o.name == n || o.python_name() == n) return &o;
  return nullptr;
}

}  // namespace scalcal::commands
