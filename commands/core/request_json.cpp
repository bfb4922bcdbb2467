// Requests as JSON (request_json.hpp).
#include "commands/core/request_json.hpp"

#include <charconv>
#include <cmath>
#include <limits>

#include "commands/core/common_options.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {
namespace {

constexpr double kUnbounded = std::numeric_limits<double>::max();

Json property(const Option& o) {
  Json p{{"description", o.help()}};
  switch (o.kind) {
    case OptionKind::integer:
      p["type"] = "integer";
      p["minimum"] = o.lo;
      p["maximum"] = o.hi;
      break;
    case OptionKind::number:
      p["type"] = "number";
      if (o.positive) p["exclusiveMinimum"] = 0;
      if (o.low != -kUnbounded) p["minimum"] = o.low;
      if (o.high != kUnbounded) p["maximum"] = o.high;
      break;
    case OptionKind::choice:
      p["type"] = "string";
      p["enum"] = o.choices;
      break;
    case OptionKind::flag:
      p["type"] = "boolean";
      break;
    case OptionKind::repeated:
      p["type"] = "array";
      p["items"] = Json{{"type", "string"}, {"minLength", 1}};
      break;
    default:  // text, positional
      if (o.takes_positions) {
        p["oneOf"] = Json::array(
            {Json{{"type", "string"}, {"minLength", 1}},
             Json{{"type", "array"},
                  {"items", {{"type", "array"}, {"items", {{"type", "number"}}}, {"minItems", 3}, {"maxItems", 3}}}}});
      } else if (o.takes_document) {
        p["oneOf"] = Json::array({Json{{"type", "string"}, {"minLength", 1}}, Json{{"type", "object"}}});
      } else {
        p["type"] = "string";
        p["minLength"] = 1;
      }
  }
  // The default as a value of the key's type; none where --help describes it instead of giving one
  // ("0 = all cores", "adaptive: ...", "required, unless --from gives it").
  if (!o.required() && !o.fallback.empty() && o.fallback_text.empty() && o.kind != OptionKind::flag) {
    long long i = 0;
    double x = 0;
    if (o.kind == OptionKind::integer && read_integer(o.fallback, i))
      p["default"] = i;
    else if (o.kind == OptionKind::number && read_number(o.fallback, x))
      p["default"] = x;
    else if (o.kind == OptionKind::repeated)
      p["default"] = Json::array({o.fallback});
    else
      p["default"] = o.fallback;
  }
  if (o.unit != "none") p["x-unit"] = o.unit;
  return p;
}

std::string number_text(const Json& j) {
  if (j.is_number_integer())
    return j.is_number_unsigned() ? std::to_string(j.get<unsigned long long>()) : std::to_string(j.get<long long>());
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, j.get<double>()).ptr;
  return std::string(buffer, end);
}

// A scalar's text as the command line would give it; empty optional for another kind.
std::optional<std::string> scalar_text(const Json& j) {
  if (j.is_string()) return j.get<std::string>();
  if (j.is_number()) return number_text(j);
  return std::nullopt;
}

void set_one(Values& values, const Option& o, const Json& j) {
  if (o.kind == OptionKind::flag) {
    if (!j.is_boolean()) throw UsageError("must be true or false");
    values.set_flag(o.name, j.get<bool>());
    return;
  }
  if (o.takes_positions && j.is_array()) {
    Program p;
    for (const auto& row : j) {
      if (!row.is_array() || row.size() != 3 || !row[0].is_number() || !row[1].is_number() || !row[2].is_number())
        throw UsageError("a program's positions must be [x, y, z] numbers");
      p.positions.emplace_back(row[0].get<double>(), row[1].get<double>(), row[2].get<double>());
    }
    values.program = p;
    values.set(o.name, "positions");  // as Python's (N, 3) array
    return;
  }
  if (o.takes_document && j.is_object()) {  // a calibration file's object itself, as Python's dict
    values.documents[o.name] = j;
    values.set(o.name, o.python_name());
    return;
  }
  if (o.kind == OptionKind::repeated) {
    if (!j.is_array()) throw UsageError("must be an array (the option is repeated)");
    for (const auto& item : j) {
      const auto text = scalar_text(item);
      if (!text) throw UsageError("each item must be a string or a number");
      values.set(o.name, *text);
    }
    return;
  }
  const auto text = scalar_text(j);
  if (!text) throw UsageError("must be a string or a number");
  values.set(o.name, *text);
}

}  // namespace

Json request_schema(const CommandTable& table) {
  Json properties = Json::object();
  Json required = Json::array();
  for (const Option& o : table.options) {
    if (o.cli_only) continue;
    properties[o.python_name()] = property(o);
    if (o.required()) required.push_back(o.python_name());
  }
  Json schema{{"$schema", "https://json-schema.org/draft/2020-12/schema"},
              {"$id", "https://scalcal.example/schema/" + table.name + ".json"},
              {"title", "scalcal " + table.name},
              {"description", table.summary},
              {"type", "object"},
              {"properties", properties},
              {"additionalProperties", false}};
  if (!required.empty()) schema["required"] = required;
  return schema;
}

void set_from_request(Values& values, const Json& request, const std::string& source) {
  if (!request.is_object()) throw UsageError(source + ": a request must be a JSON object");
  for (const auto& [key, value] : request.items()) {
    const Option* o = values.table().find(key);
    if (!o || o->cli_only || o->python_name() != key)
      throw UsageError(source + ": key '" + key + "': " + values.table().name + " has no such field");
    try {
      set_one(values, *o, value);
    } catch (const UsageError& e) {
      std::string reason = e.what();
      const std::string prefix = option_word(o->name) + ": ";
      if (reason.rfind(prefix, 0) == 0) reason = reason.substr(prefix.size());
      throw UsageError(source + ": key '" + key + "': " + reason);
    }
  }
}

const CommandTable& schema_table() {
  Option command;
  command.name = "COMMAND";
  command.kind = OptionKind::positional;
  command.value_name = "COMMAND";
  command.what = "the command whose request to describe (scalcal help lists them)";
  command.fallback = kRequired;
  static const CommandTable table{
      "schema",
      words("the JSON Schema of a command's request (the JSON that `{request FILE}` and Python's keywords take)"),
      95,
      {command, out_option("write the schema to FILE instead of standard output")}};
  return table;
}

}  // namespace scalcal::commands
