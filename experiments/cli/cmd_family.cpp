// `scalcal family NAME [--param KEY=VALUE]... [--model NAME] [--json]`: the exact criteria of a family
// member, or closed forms in symbolic parameters (commands/research/family.hpp).
#include <iostream>

#include "commands/research/family.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"

namespace scalcal::cli {
namespace {

int run(const commands::Values& v) {
  const auto r = commands::family(commands::family_request(v));
  print_warnings("family", r.warnings);
  if (v.flag("--json")) {
    print_json(commands::to_json(r));
    return 0;
  }
  std::cout << "family " << r.family;
  for (const auto& [k, text] : r.params) std::cout << " " << k << "=" << text;
  if (!is_default_model(r.model))
    std::cout << " (model " << model_name(r.model) << ", D = N^" << model_parameters(r.model) << " det K)";
  std::cout << "\npositions N = " << r.positions << "\n";
  for (const auto& row : r.rows) {
    std::cout << "  " << row.key << " = " << (row.exact ? row.text : std::string("(no closed form)"));
    if (row.number) std::cout << "  ~ " << *row.number;
    std::cout << "\n";
  }
  return 0;
}

const Registration reg(commands::family_table(), run);

}  // namespace
}  // namespace scalcal::cli
