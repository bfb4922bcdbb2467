#include "experiments/cli/options.hpp"

#include <charconv>
#include <cmath>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

namespace scalcal::cli {

std::string describe(const Help& help, const std::string& bound_value) {
  const std::string fallback = help.fallback.empty() ? bound_value : help.fallback;
  return help.what + " (unit: " + help.unit + "; default: " + (fallback.empty() ? "none" : fallback) + ")";
}

namespace {

// Whole-text reads: from_chars stops at the first character it cannot use, so a shorter `ptr`
// than the end means trailing garbage.
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

std::string in_quotes(const std::string& s) { return "'" + s + "'"; }

CLI::Validator integer_in(long long lo, long long hi) {
  return CLI::Validator(
      [lo, hi](std::string& s) -> std::string {
        long long x = 0;
        if (!read_integer(s, x) || x < lo || x > hi)
          return fmt::format("must be an integer in {}..{}, got {}", lo, hi, in_quotes(s));
        s = std::to_string(x);
        return {};
      },
      "");
}

CLI::Validator number_check(NumberRange range) {
  return CLI::Validator(
      [range](std::string& s) -> std::string {
        double x = 0;
        if (range.positive) {
          if (!read_number(s, x)) return "must be a positive number, got " + in_quotes(s);
          if (!(x > 0)) return "must be positive, got " + in_quotes(s);
        } else if (!read_number(s, x) || x < range.lo || x > range.hi) {
          return fmt::format("must be a number in {}..{}, got {}", range.lo, range.hi, in_quotes(s));
        }
        s = fmt::format("{}", x);
        return {};
      },
      "");
}

CLI::Validator not_empty() {
  return CLI::Validator([](std::string& s) -> std::string { return s.empty() ? "must not be empty" : ""; }, "");
}

CLI::Validator one_of(const std::vector<std::string>& choices) {
  return CLI::Validator(
      [choices](std::string& s) -> std::string {
        for (const auto& c : choices)
          if (s == c) return {};
        std::string list;
        for (std::size_t i = 0; i < choices.size(); ++i)
          list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
        return "must be " + list + ", got " + in_quotes(s);
      },
      "");
}

void required_if_so(CLI::Option* option, const Help& help) {
  if (help.fallback == kRequired) option->required();
}

template <class Int>
void add_integer_option(CLI::App& app, const std::string& name, Int& target, long long lo, long long hi,
                        const Help& help) {
  required_if_so(
      app.add_option(name, target, describe(help, std::to_string(target)))->transform(integer_in(lo, hi))->type_name("INT"),
      help);
}

}  // namespace

void add_integer(CLI::App& app, const std::string& name, int& target, long long lo, long long hi, const Help& help) {
  add_integer_option(app, name, target, lo, hi, help);
}
void add_integer(CLI::App& app, const std::string& name, long long& target, long long lo, long long hi,
                 const Help& help) {
  add_integer_option(app, name, target, lo, hi, help);
}
void add_integer(CLI::App& app, const std::string& name, std::uint64_t& target, long long lo, long long hi,
                 const Help& help) {
  add_integer_option(app, name, target, lo, hi, help);
}

void add_number(CLI::App& app, const std::string& name, double& target, NumberRange range, const Help& help) {
  required_if_so(app.add_option(name, target, describe(help, fmt::format("{}", target)))
                     ->transform(number_check(range))
                     ->type_name("NUM"),
                 help);
}

void add_text(CLI::App& app, const std::string& name, std::string& target, const std::string& value_name,
              const Help& help) {
  required_if_so(app.add_option(name, target, describe(help, target))->check(not_empty())->type_name(value_name), help);
}

void add_checked_text(CLI::App& app, const std::string& name, std::string& target, const std::string& value_name,
                      const Help& help, std::function<std::string(const std::string&)> why_bad) {
  required_if_so(app.add_option(name, target, describe(help, target))
                     ->type_name(value_name)
                     ->check(CLI::Validator([why_bad](std::string& s) { return why_bad(s); }, "")),
                 help);
}

void add_choice(CLI::App& app, const std::string& name, std::string& target, const std::vector<std::string>& choices,
                const Help& help) {
  std::string names;
  for (const auto& c : choices) names += (names.empty() ? "" : "|") + c;
  required_if_so(app.add_option(name, target, describe(help, target))->check(one_of(choices))->type_name(names), help);
}

void add_switch(CLI::App& app, const std::string& name, bool& target, const std::string& what) {
  app.add_flag(name, target, what);
}

void add_positional(CLI::App& app, const std::string& name, std::string& target, const std::string& what) {
  app.add_option(name, target, what)->required();
}

void add_repeatable(CLI::App& app, const std::string& name, std::vector<std::string>& target,
                    const std::string& value_name, const Help& help) {
  app.add_option(name, target, describe(help, ""))->type_name(value_name)->allow_extra_args(false);
}

}  // namespace scalcal::cli
