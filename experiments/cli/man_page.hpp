// Man pages (roff, man(7) macros) made from the same option tables as the parser and --help:
// scalcal.1 lists the subcommands, scalcal-SUB.1 gives every option of SUB with its unit, default and
// accepted values. `scalcal --man [SUB]` prints one; the build writes them all (cmake/man_pages.cmake).
#pragma once
#include <string>
#include <vector>

#include "experiments/cli/command.hpp"

namespace scalcal::cli {

// scalcal-NAME(1) for one subcommand's table.
std::string man_page(const commands::CommandTable& table, const std::string& version);

// scalcal(1): the overview, every subcommand with its summary and a SEE ALSO to its page.
std::string man_overview(const std::vector<Command>& commands, const std::string& version);

}  // namespace scalcal::cli
