// The one registry of program names (program_names.hpp).
#include "numeric/program/program_names.hpp"

#include <mutex>

namespace scalcal {

// Defined in catalogue.cpp: the paper's programs, always the first entry.
ProgramNames paper_program_names();

namespace {

struct Registry {
  std::mutex mutex;
  std::vector<ProgramNames> entries{paper_program_names()};
};

Registry& registry() {
  static Registry r;
  return r;
}

}  // namespace

void register_program_names(ProgramNames entry) {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  for (auto& e : r.entries)
    if (e.key == entry.key) {
      e = std::move(entry);
      return;
    }
  r.entries.push_back(std::move(entry));
}

std::vector<ProgramNames> program_names() {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  return r.entries;
}

}  // namespace scalcal
