// A command's option table (commands/core/option_table.hpp) as CLI11 options: each value is checked by
// the table's own rule, so a bad value fails with the option's name and the reason, and --help
// shows the table's help lines. Only this file and options.cpp, main.cpp see CLI11 itself.
#pragma once
#include <functional>

#include "commands/core/values.hpp"

namespace CLI {
class App;
}

namespace scalcal::cli {

// Declares the table's options (not the CLI-only ones' behaviour: they are options like any other)
// on `app`; the function returned gives the parsed values once CLI11 has run.
// The value an option takes, as --help and the man pages show it: its value name, INT, NUM, the
// choices joined by |, or TEXT.
std::string type_name(const commands::Option& option);

std::function<commands::Values()> add_table_options(CLI::App& app, const commands::CommandTable& table);

// The help line of --request FILE, which every table command takes (the man page shows it too).
std::string request_help(const commands::CommandTable& table);

}  // namespace scalcal::cli
