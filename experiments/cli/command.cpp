#include "experiments/cli/command.hpp"

#include <algorithm>
#include <unistd.h>

namespace scalcal::cli {

namespace {
std::vector<Command>& registry() {
  static std::vector<Command> r;
  return r;
}
}  // namespace

Registration::Registration(Command c) {
  auto& r = registry();
  r.push_back(std::move(c));
  std::stable_sort(r.begin(), r.end(), [](const Command& a, const Command& b) { return a.order < b.order; });
}

const std::vector<Command>& commands() { return registry(); }

bool progress_enabled() { return isatty(STDERR_FILENO) != 0; }

}  // namespace scalcal::cli
