// How a message names an option, in the words of the front end that runs it: the shell's
// "--threshold-factor 4", Python's "threshold_factor=4". The library writes "{threshold-factor 4}" and
// `words()` renders it; each front end sets its style once, at start (the CLI keeps the default).
#pragma once
#include <string>
#include <string_view>

namespace scalcal {

enum class OptionStyle {
  cli,     // --name, --name VALUE
  python,  // name=, name=VALUE (dashes as underscores, a Python keyword with a trailing underscore)
};

// The process-wide style (one front end per process; read-only once work starts).
void set_option_style(OptionStyle style);
OptionStyle option_style();

// `text` with each "{name}" or "{name VALUE}" (name: a lowercase letter, then lowercase letters, digits
// and dashes) rendered in the style; any other brace is text. In Python's style a text ending in
// "{name} " (its value follows, appended by the caller) renders "name=" without the space.
std::string words(std::string_view text);

// Python's keyword for an option ("--threshold-factor" -> "threshold_factor", "PROGRAM" -> "program", "--from" ->
// "from_": a Python keyword takes a trailing underscore, as PEP 8 has it). The front ends' arguments use it too.
std::string python_keyword(std::string_view name);

// One option as the field an error is about ("threshold-factor" or "--threshold-factor"): the shell's
// "--threshold-factor", Python's "threshold_factor" (as Python names a bad argument: "region: 'cap:500': ...").
std::string option_word(std::string_view name);

}  // namespace scalcal
