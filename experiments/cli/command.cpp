// The subcommand registry, progress on a terminal and warnings on stderr (command.hpp).
#include "experiments/cli/command.hpp"

#include "experiments/cli/table_options.hpp"
#include "numeric/io/input_error.hpp"

#include <unistd.h>
#include <algorithm>
#include <iostream>
#include <memory>

namespace scalcal::cli {

namespace {
std::vector<Command>& registry() {
  static std::vector<Command> r;
  return r;
}
}  // namespace

Registration::Registration(const commands::CommandTable& table, std::function<int(const commands::Values&)> run)
    : Registration(Command{table.name, table.usage(), table.summary, table.order,
                           [&table, run](CLI::App& app) {
                             const auto values = add_table_options(app, table);
                             return Runner([values, run] { return run(values()); });
                           },
                           &table}) {}

Registration::Registration(Command c) {
  auto& r = registry();
  r.push_back(std::move(c));
  std::stable_sort(r.begin(), r.end(), [](const Command& a, const Command& b) { return a.order < b.order; });
}

const std::vector<Command>& commands() { return registry(); }

bool progress_enabled() { return isatty(STDERR_FILENO) != 0; }

commands::Progress terminal_progress(const std::string& command) {
  if (!progress_enabled()) return {};
  auto counting = std::make_shared<bool>(false);  // a "\r" line is open
  return [command, counting](std::string_view stage, int done, int total) {
    if (stage == "starts") {
      std::cerr << "\rstart " << done << "/" << total << (done == total ? "\n" : "") << std::flush;
      *counting = done != total;
      return;
    }
    if (*counting) std::cerr << "\n";
    *counting = false;
    std::cerr << command << ": " << stage << "\n";
  };
}

void print_warnings(const std::string& command, const commands::Warnings& warnings) {
  for (const auto& w : warnings)
    std::cerr << "scalcal " << command << ": " << (w.subject.empty() ? "" : display_name(w.subject) + ": ")
              << "warning: " << w.message << "\n";
}

}  // namespace scalcal::cli
