// Typed options of the subcommands on top of CLI11. Each option reads its whole text strictly (a
// decimal integer or a finite number within its range, a non-empty path, one of its choices), so a
// bad value fails with the option's name and the reason; its help line states its unit and default.
// Only options.cpp, synthesis_cli.cpp and main.cpp see CLI11 itself: it costs ~10 s of compile
// time in every file that includes it.
#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace scalcal::cli {

// The help text of an option: what it sets, its unit ("none" when it has none) and its default
// (empty: the value the option is bound to; kRequired for a required option, which makes it so).
struct Help {
  std::string what;
  std::string unit = "none";
  std::string fallback = "";
};
inline constexpr const char* kRequired = "none, required";

// "what (unit: U; default: V)"
std::string describe(const Help& help, const std::string& bound_value);

// The accepted values of a number option: finite and x > 0 (positive), or finite and lo <= x <= hi.
struct NumberRange {
  double lo = -std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::max();
  bool positive = false;
};
inline NumberRange number_in(double lo, double hi) { return {lo, hi, false}; }

// The accepted values of an integer option, where the Python module takes the same argument too.
struct IntegerRange {
  long long lo, hi;
};
inline NumberRange positive_number() { return {0, std::numeric_limits<double>::max(), true}; }

// Integers are read as decimal text (CLI11 alone would read "010" as octal and "-1" as a huge
// unsigned number), then range-checked.
void add_integer(CLI::App& app, const std::string& name, int& target, long long lo, long long hi, const Help& help);
void add_integer(CLI::App& app, const std::string& name, long long& target, long long lo, long long hi,
                 const Help& help);
void add_integer(CLI::App& app, const std::string& name, std::uint64_t& target, long long lo, long long hi,
                 const Help& help);
void add_number(CLI::App& app, const std::string& name, double& target, NumberRange range, const Help& help);
void add_text(CLI::App& app, const std::string& name, std::string& target, const std::string& value_name,
              const Help& help);
// A text option with its own check: `why_bad` returns the reason the text is refused, or "".
void add_checked_text(CLI::App& app, const std::string& name, std::string& target, const std::string& value_name,
                      const Help& help, std::function<std::string(const std::string&)> why_bad);
void add_choice(CLI::App& app, const std::string& name, std::string& target, const std::vector<std::string>& choices,
                const Help& help);
void add_switch(CLI::App& app, const std::string& name, bool& target, const std::string& what);
// A required positional argument (e.g. PROGRAM).
void add_positional(CLI::App& app, const std::string& name, std::string& target, const std::string& what);
// A repeatable option, one value per use (--param KEY=VALUE --param ...).
void add_repeatable(CLI::App& app, const std::string& name, std::vector<std::string>& target,
                    const std::string& value_name, const Help& help);

}  // namespace scalcal::cli
