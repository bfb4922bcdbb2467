// The JSON form of results, shared by the CLI (--json, --out) and the Python module (dicts):
// nlohmann::ordered_json keeps keys in the documented order; doubles print in the shortest text
// that reads back to the same bits; NaN and infinity print as null.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "numeric/model/paper9.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::commands {

using Json = nlohmann::ordered_json;

Json program_json(const Program& program);  // [[x, y, z], ...]
Json matrix_json(const Mat9& m);            // nine rows of nine numbers
// dump(), with bytes that are not UTF-8 (a file name in another encoding) written as U+FFFD, never
// an exception half-way through the output.
std::string json_text(const Json& j, int indent = -1);

// The JSON files scalcal reads (calibrations, meters) are a few levels deep: a text nested deeper
// than this is refused as soon as the parser reaches that depth, so 60 MB of '[' costs no more
// memory than the text itself.
inline constexpr int kMaxJsonDepth = 64;
// Parses `text`; a syntax error, a number out of range (1e400) or nesting deeper than kMaxJsonDepth
// throws InputError naming `file` and "not <expected>: <reason>".
Json parse_json_file_text(const std::string& text, const std::string& file, const std::string& expected = "JSON");

}  // namespace scalcal::commands
