// The subcommand registry, progress on a terminal and warnings on stderr (command.hpp).
#include "experiments/cli/command.hpp"

#include "experiments/cli/output_file.hpp"
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

namespace {

// The files given as "-" (standard output): at most one, and then the report goes to stderr.
void route_standard_output(const commands::CommandTable& table, const commands::Values& v) {
  std::vector<std::string> dashes;
  for (const auto& o : table.options)
    if (o.writes_file && v.given(o.name) && v.text(o.name) == "-") dashes.push_back(o.name);
  if (dashes.size() > 1)
    throw UsageError("options " + dashes[0] + " and " + dashes[1] +
                     " both write to standard output ('-'): give one of them a file");
  commands::check_distinct_outputs(v);
  if (dashes.size() == 1) divert_report();
}

}  // namespace

Registration::Registration(const commands::CommandTable& table, std::function<int(const commands::Values&)> run)
    : Registration(Command{table.name, table.usage(), table.summary, table.order,
                           [&table, run](CLI::App& app) {
                             const auto values = add_table_options(app, table);
                             return Runner([values, run, &table] {
                               const commands::Values v = values();
                               route_standard_output(table, v);
                               return run(v);
                             });
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
