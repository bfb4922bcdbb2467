// JSON output of the CLI through nlohmann::ordered_json: keys stay in the documented order, doubles
// print in the shortest form that reads back to the same bits, NaN and infinity print as null.
#pragma once
#include <ostream>

#include <nlohmann/json.hpp>

#include "numeric/model/paper9.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::cli {

using Json = nlohmann::ordered_json;

Json program_json(const Program& program);  // [[x, y, z], ...]
Json matrix_json(const Mat9& m);            // nine rows of nine numbers
void print_json(const Json& j);             // to stdout, indented, one trailing newline
void write_json(std::ostream& out, const Json& j);  // the same to any stream
std::string json_text(const Json& j, int indent = -1);  // dump(), with invalid UTF-8 replaced by U+FFFD

}  // namespace scalcal::cli
