// A command's request as one JSON object, its keys the options' Python names: the JSON Schema that the
// option table implies (published in docs/schema/, `scalcal schema COMMAND`), and the values a request
// gives, checked by the same rules as the command line's and Python's. So a request can be written
// by a program, stored beside its result, or handed to another process, and read back the same way.
#pragma once
#include <string>

#include "commands/core/json.hpp"
#include "commands/core/values.hpp"

namespace scalcal::commands {

// JSON Schema (draft 2020-12) of the request: each option but the CLI-only ones (how the CLI presents
// a result) as a property with its type, range or choices, default, unit and help line; the required
// ones listed; no other key allowed.
Json request_schema(const CommandTable& table);

// Sets `values` from `request` (source: the file it came from, for messages). A key names an option
// by its Python name; strings, numbers, booleans (flags) and arrays (repeated options, or a program's
// [[x, y, z], ...]) are read as the command line reads their text. Throws UsageError naming the source
// and the key ("req.json: key 'positions': must be an integer in 3..1000, got '2'").
void set_from_request(Values& values, const Json& request, const std::string& source);

// `schema COMMAND [--out FILE]`: the JSON Schema of a command's request.
const CommandTable& schema_table();

}  // namespace scalcal::commands
