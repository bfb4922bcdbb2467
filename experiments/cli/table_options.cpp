// CLI11 options from an option table (table_options.hpp).
#include "experiments/cli/table_options.hpp"

#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands/core/request_json.hpp"
#include "commands/core/usage_error.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::cli {
namespace {

using commands::Option;
using commands::OptionKind;

// What CLI11 binds the options to, kept alive by the returned function.
struct Storage {
  std::map<std::string, std::string> text;
  std::map<std::string, std::vector<std::string>> lists;
  std::map<std::string, bool> flags;
  std::map<std::string, CLI::Option*> bound;
};

CLI::Validator table_check(const Option& o) {
  return CLI::Validator([o](std::string& s) { return o.check(s); }, "");
}

// The values of a --request file (commands/core/request_json.hpp); InputError for a file that cannot
// be read or is not JSON.
commands::Values read_request(const commands::CommandTable& table, const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  commands::Json j;
  try {
    j = commands::Json::parse(text.str());
  } catch (const std::exception& e) {
    throw InputError(path, 0, "not JSON (" + std::string(e.what()) + ")");
  }
  commands::Values v(table);
  commands::set_from_request(v, j, path);
  return v;
}

}  // namespace

std::string type_name(const Option& o) {
  if (!o.value_name.empty()) return o.value_name;
  if (o.kind == OptionKind::integer) return "INT";
  if (o.kind == OptionKind::number) return "NUM";
  if (o.kind == OptionKind::choice) {
    std::string names;
    for (const auto& c : o.choices) names += (names.empty() ? "" : "|") + c;
    return names;
  }
  return "TEXT";
}

std::string request_help(const commands::CommandTable& table) {
  return "read the request from FILE: a JSON object, keys the Python names (`scalcal schema " + table.name +
         "`); options given on the command line too are refused (unit: file path; default: none)";
}

std::function<commands::Values()> add_table_options(CLI::App& app, const commands::CommandTable& table) {
  auto store = std::make_shared<Storage>();
  for (const Option& o : table.options) {
    CLI::Option* opt = nullptr;
    switch (o.kind) {
      case OptionKind::flag:
        opt = app.add_flag(o.name, store->flags[o.name], o.help());
        break;
      case OptionKind::repeated:
        opt = app.add_option(o.name, store->lists[o.name], o.help())
                  ->type_name(type_name(o))
                  ->allow_extra_args(false)
                  ->check(table_check(o));
        break;
      default:
        // Required is checked once the values are gathered: --request may give it.
        opt = app.add_option(o.name, store->text[o.name], o.help())->type_name(type_name(o))->transform(table_check(o));
    }
    store->bound[o.name] = opt;
  }
  auto request = std::make_shared<std::string>();
  CLI::Option* request_option = app.add_option("--request", *request, request_help(table))->type_name("FILE");
  const commands::CommandTable* t = &table;
  return [store, t, request, request_option] {
    commands::Values v(*t);
    if (request_option->count() > 0) v = read_request(*t, *request);
    for (const Option& o : t->options) {
      if (store->bound[o.name]->count() == 0) continue;
      if (v.given(o.name))
        throw UsageError((o.kind == OptionKind::positional ? o.name : "option " + o.name) +
                         " is given both on the command line and in " + *request);
      if (o.kind == OptionKind::flag)
        v.set_flag(o.name, store->flags[o.name]);
      else if (o.kind == OptionKind::repeated)
        for (const auto& s : store->lists[o.name]) v.set(o.name, s);
      else
        v.set(o.name, store->text[o.name]);
    }
    for (const Option& o : t->options)
      if (o.required() && !v.given(o.name))
        throw UsageError((o.kind == OptionKind::positional ? o.name : "option " + o.name) + " is required" +
                         (request_option->count() > 0
                              ? " (on the command line, or as key '" + o.python_name() + "' in " + *request + ")"
                              : ""));
    return v;
  };
}

}  // namespace scalcal::cli
