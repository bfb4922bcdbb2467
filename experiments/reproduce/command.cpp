// `scalcal reproduce` as a command (command.hpp).
#include "experiments/reproduce/command.hpp"

#include "commands/core/common_options.hpp"

namespace scalcal::reproduce {

const commands::CommandTable& reproduce_table() {
  using namespace commands;
  Option quiet = flag_option("--quiet", "no progress on stderr (by default one line per stage, with the time left)");
  quiet.cli_only = true;
  static const CommandTable table{
      "reproduce",
      "regenerate the paper's Figs. 4-9 and Tables 1-3 and the new figures (PDF, PNG, SVG, CSV, REPORT.md)",
      90,
      {text_option("--out", "DIR", "folder for the figures, their data and REPORT.md", "folder path", "results"),
       flag_option("--quick", "small sweeps (2-4 optimiser starts, few N), as the tests run"), threads_option(),
       quiet}};
  return table;
}

Options reproduce_options(const commands::Values& v) {
  Options o;
  o.out = v.text("--out");
  o.quick = v.flag("--quick");
  o.threads = static_cast<int>(v.integer("--threads"));
  return o;
}

commands::Json to_json(const RunSummary& s) {
  return commands::Json{{"report", s.report.string()}, {"seconds", s.seconds}};
}

}  // namespace scalcal::reproduce
