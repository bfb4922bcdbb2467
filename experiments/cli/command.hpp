// The subcommand registry of the `scalcal` CLI. Each cmd_*.cpp registers its subcommand with a
// static Registration, so adding one touches no shared table; main.cpp builds the CLI11 parser from
// the registry. Bad options or input end as one line on stderr and exit 2 (main.cpp).
#pragma once
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands/core/progress.hpp"
#include "commands/core/usage_error.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"

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
  const commands::CommandTable* table = nullptr;  // its options (the man page is made from it)
};

struct Registration {
  explicit Registration(Command c);
  // A command whose options are a table of commands/ (parsed by table_options.hpp); `run` gets the
  // checked values and returns the exit status.
  Registration(const commands::CommandTable& table, std::function<int(const commands::Values&)> run);
};

const std::vector<Command>& commands();

// True when stderr is a terminal: long work shows progress only then.
bool progress_enabled();

// Progress on a terminal's stderr ("\rstart 5/16", "limits: D on cap:30"); empty when stderr is
// not a terminal.
commands::Progress terminal_progress(const std::string& command);

// Each warning as one stderr line: "scalcal COMMAND: SUBJECT: warning: MESSAGE".
void print_warnings(const std::string& command, const commands::Warnings& warnings);

}  // namespace scalcal::cli
