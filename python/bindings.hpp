// Every command of commands/ the Python module offers, by name: its option table and how to run it
// from checked Values, with its result as JSON (the CLI's --json object), its warnings and the exit
// status the CLI would give (1: a result that did not converge).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "commands/core/json.hpp"
#include "commands/core/progress.hpp"
#include "commands/core/values.hpp"
#include "commands/core/warning.hpp"

namespace scalcal::python {

struct Output {
  commands::Json json;
  commands::Warnings warnings;
  int status = 0;
};

struct Binding {
  const commands::CommandTable* table;
  std::function<Output(const commands::Values&, const commands::Progress&)> run;
};

const std::vector<Binding>& bindings();
const Binding& binding(const std::string& name);  // throws std::out_of_range

}  // namespace scalcal::python
