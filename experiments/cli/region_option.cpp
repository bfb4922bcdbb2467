#include "experiments/cli/region_option.hpp"

#include <cstdio>
#include <iostream>

#include "commands/region_request.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/options.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::cli {

void add_region_option(CLI::App& app, std::vector<std::string>& specs) {
  add_repeatable(app, "--region", specs, "SPEC",
                 {"directions the bench reaches; repeat for a union: sphere, cap:DEG[:X,Y,Z], band:LO:HI[:X,Y,Z], "
                  "faces:DEG, candidates:FILE",
                  "degrees", "sphere"});
}

Region resolve_region(const std::vector<std::string>& specs, const std::string& command) {
  commands::Warnings warnings;
  Region region = commands::resolve_region(specs, warnings);
  print_warnings(command, warnings);
  return region;
}

std::vector<ExtraColumn> region_columns(const Region& region, const Program& program) {
  return commands::region_columns(region, program);
}

}  // namespace scalcal::cli
