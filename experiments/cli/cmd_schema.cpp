// `scalcal schema COMMAND [--out FILE]`: the JSON Schema of a command's request, from its option table
// (commands/core/request_json.hpp); docs/schema/ holds every command's, checked against this by ctest.
#include <iostream>

#include "commands/core/build_features.hpp"
#include "commands/core/request_json.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

int run(const commands::Values& v) {
  const std::string name = v.text("COMMAND");
  for (const Command& c : commands()) {
    if (c.name != name) continue;
    if (!c.table) throw UsageError("schema: " + name + " takes no request (it has no option table)");
    const std::string text = commands::json_text(commands::request_schema(*c.table), 2) + "\n";
    if (v.given("--out")) {
      OutputFile out(v.text("--out"));
      out.stream() << text;
      out.close();
    } else {
      std::cout << text;
    }
    return 0;
  }
  for (const commands::LackingCommand& c : commands::lacking_commands())
    if (c.name == name) throw UsageError("schema: " + commands::lacking_message(c));
  throw UsageError("schema: no command '" + name + "' (scalcal help lists them)");
}

const Registration reg(commands::schema_table(), run);

}  // namespace
}  // namespace scalcal::cli
