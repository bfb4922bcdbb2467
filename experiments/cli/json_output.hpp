// JSON on the CLI's stdout and in its files: the results' JSON form (commands/core/json.hpp), printed
// indented with one trailing newline.
#pragma once
#include <ostream>

#include "commands/core/json.hpp"

namespace scalcal::cli {

using commands::Json;
using commands::json_text;
using commands::matrix_json;
using commands::program_json;

void print_json(const Json& j);                     // to stdout
void write_json(std::ostream& out, const Json& j);  // the same to any stream

}  // namespace scalcal::cli
