// Typed options of the subcommands on top of CLI11. Each option reads its whole text strictly (a
// decimal integer or a finite number within its range, a non-empty path, one of its choices), so a
// bad value fails with the option's name and the reason; its help line states its unit and default.
#pragma once
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace scalcal::cli {

// The help text of an option: what it sets, its unit ("none" when it has none) and its default
// (empty: the value the option is bound to; kRequired for a required option).
struct Help {
  std::string what;
  std::string unit = "none";
  std::string fallback = "";
};
inline constexpr const char* kRequired = "none, required";

// "what (unit: U; default: V)"
std::string describe(const Help& help, const std::string& bound_value);

// Validators that also rewrite the text into the form CLI11 converts as meant (decimal integers:
// CLI11 alone would read "010" as octal and "-1" as a huge unsigned number).
CLI::Validator integer_in(long long lo, long long hi);
CLI::Validator number_in(double lo, double hi);  // finite, lo <= x <= hi
CLI::Validator positive_number();                // finite, x > 0
CLI::Validator not_empty();
CLI::Validator one_of(const std::vector<std::string>& choices);

template <class Int>
CLI::Option* add_integer(CLI::App& app, const std::string& name, Int& target, long long lo, long long hi,
                         const Help& help) {
  return app.add_option(name, target, describe(help, std::to_string(target)))
      ->transform(integer_in(lo, hi))
      ->type_name("INT");
}

CLI::Option* add_number(CLI::App& app, const std::string& name, double& target, const CLI::Validator& check,
                        const Help& help);
CLI::Option* add_text(CLI::App& app, const std::string& name, std::string& target, const std::string& value_name,
                      const Help& help);
CLI::Option* add_choice(CLI::App& app, const std::string& name, std::string& target,
                        const std::vector<std::string>& choices, const Help& help);
CLI::Option* add_switch(CLI::App& app, const std::string& name, bool& target, const std::string& what);

}  // namespace scalcal::cli
