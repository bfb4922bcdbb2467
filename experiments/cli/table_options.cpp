// CLI11 options from an option table (table_options.hpp).
#include "experiments/cli/table_options.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

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
        opt = app.add_option(o.name, store->text[o.name], o.help())->type_name(type_name(o))->transform(table_check(o));
        if (o.required()) opt->required();
    }
    store->bound[o.name] = opt;
  }
  const commands::CommandTable* t = &table;
  return [store, t] {
    commands::Values v(*t);
    for (const Option& o : t->options) {
      if (store->bound[o.name]->count() == 0) continue;
      if (o.kind == OptionKind::flag)
        v.set_flag(o.name, store->flags[o.name]);
      else if (o.kind == OptionKind::repeated)
        for (const auto& s : store->lists[o.name]) v.set(o.name, s);
      else
        v.set(o.name, store->text[o.name]);
    }
    return v;
  };
}

}  // namespace scalcal::cli
