// The subcommand registry of the `scalcal` CLI and its argument reader. Each cmd_*.cpp file
// registers its subcommand with a static Registration, so adding one touches no shared table.
// Usage errors throw UsageError and input errors InputError: main prints them and exits 2.
#pragma once
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace scalcal::cli {

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The arguments after the subcommand name. Options are read (and consumed) by name; whatever
// is left must be positional, and an unknown --option is a usage error.
class Args {
 public:
  explicit Args(std::vector<std::string> tokens) : tokens_(std::move(tokens)) {}

  bool flag(const std::string& name);                        // --name
  std::optional<std::string> value(const std::string& name);  // --name V or --name=V
  std::vector<std::string> values(const std::string& name);  // repeatable --name V
  std::string text(const std::string& name, const std::string& fallback);
  long long integer(const std::string& name, long long fallback, long long lo, long long hi);
  double real(const std::string& name, double fallback);
  // The remaining positional arguments; call after every option has been read.
  std::vector<std::string> positionals();

 private:
  std::vector<std::string> tokens_;
};

struct Command {
  std::string name;
  std::string usage;    // e.g. "evaluate PROGRAM [--json]"
  std::string summary;  // one line
  int order = 100;      // position in `scalcal help`
  std::function<int(Args&)> run;
};

struct Registration {
  explicit Registration(Command c);
};

const std::vector<Command>& commands();

// True when stderr is a terminal: long work shows progress only then.
bool progress_enabled();

}  // namespace scalcal::cli
