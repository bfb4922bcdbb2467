// Shared pieces of the synthesis subcommands (optimize, random, sweep): reading a criterion
// option, a program as a JSON list of [x, y, z], and progress lines on a terminal.
#pragma once
#include <optional>
#include <string>

#include "experiments/command.hpp"
#include "experiments/json.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::cli {

CriterionKind criterion_option(Args& args, const std::string& fallback);
Json program_json(const Program& program);
// Writes the program as CSV (x,y,z,alpha1_deg,alpha2_deg); throws InputError if it cannot.
void write_program_file(const std::string& path, const Program& program);

}  // namespace scalcal::cli
