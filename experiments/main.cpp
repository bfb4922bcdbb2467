// scalcal: the one CLI of the toolkit. Dispatches to the registered subcommands; every usage or
// input error becomes a one-line message on stderr and exit status 2.
#include <iostream>
#include <string>
#include <vector>

#include "experiments/command.hpp"
#include "numeric/io/input_error.hpp"

namespace {

void print_help(std::ostream& out) {
  out << "scalcal: scalar calibration programs for vector meters\n\nusage: scalcal COMMAND [options]\n\n";
  for (const auto& c : scalcal::cli::commands()) out << "  " << c.usage << "\n      " << c.summary << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    print_help(args.empty() ? std::cerr : std::cout);
    return args.empty() ? 2 : 0;
  }
  const std::string name = args[0];
  for (const auto& c : scalcal::cli::commands()) {
    if (c.name != name) continue;
    scalcal::cli::Args rest(std::vector<std::string>(args.begin() + 1, args.end()));
    try {
      if (rest.flag("help")) {
        std::cout << "usage: scalcal " << c.usage << "\n" << c.summary << "\n";
        return 0;
      }
      return c.run(rest);
    } catch (const scalcal::cli::UsageError& e) {
      std::cerr << "scalcal " << name << ": " << e.what() << "\nusage: scalcal " << c.usage << "\n";
      return 2;
    } catch (const scalcal::InputError& e) {
      std::cerr << "scalcal " << name << ": " << e.what() << "\n";
      return 2;
    } catch (const std::exception& e) {
      std::cerr << "scalcal " << name << ": internal error: " << e.what() << "\n";
      return 1;
    }
  }
  std::cerr << "scalcal: unknown command '" << name << "' (try `scalcal help`)\n";
  return 2;
}
