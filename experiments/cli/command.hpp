// The subcommand registry of the `scalcal` CLI. Each cmd_*.cpp registers its subcommand with a
// static Registration, so adding one touches no shared table; main.cpp builds the CLI11 parser from
// the registry. Bad options or input end as one line on stderr and exit 2 (main.cpp).
#pragma once
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands/usage_error.hpp"

namespace CLI {
class App;
}

namespace scalcal::cli {

// A usage error found after parsing (e.g. two options that contradict each other): exit 2.
using scalcal::UsageError;

using Runner = std::function<int()>;

struct Command {
  std::string name;
  std::string usage;    // e.g. "evaluate PROGRAM [--out FILE] [--json]", shown by `scalcal help`
  std::string summary;  // one line
  int order = 100;      // position in `scalcal help`
  // Declares the options on `app`, bound to state that the returned runner owns.
  std::function<Runner(CLI::App& app)> setup;
};

struct Registration {
  explicit Registration(Command c);
};

const std::vector<Command>& commands();

// True when stderr is a terminal: long work shows progress only then.
bool progress_enabled();

}  // namespace scalcal::cli
