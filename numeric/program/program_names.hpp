// The one registry of program names. Every PROGRAM argument (evaluate, optimize --from, augment,
// polish, certify, ...) and every catalogue row resolves here: numeric registers the paper's programs
// (catalogue.cpp), and each symbolic family file adds its own names when a front end starts.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "numeric/program/program.hpp"

namespace scalcal {

// A program shown by `scalcal catalogue` (and by the reproduction for its group).
struct ProgramListing {
  std::string name;
  std::string description;
  std::string source;  // where the paper, its references or scalcal gives it
};

struct ProgramNames {
  std::string key;      // unique; registering the same key again replaces the entry
  std::string pattern;  // the names it resolves, for messages and help: rotation-K[-pDEG]
  std::string group;    // "paper", "family", "jig", "test": how the catalogue and the reproduction group it
  // The program of `name`; nullopt when `name` is not one of this entry's names; throws InputError
  // when it is one of them but malformed or out of range.
  std::function<std::optional<Program>(const std::string& name)> resolve;
  std::vector<ProgramListing> listed;
};

// Adds (or replaces, by key) an entry; entries are tried in registration order.
void register_program_names(ProgramNames entry);

// Every registered entry: the paper's programs first, then the families in their order.
std::vector<ProgramNames> program_names();

}  // namespace scalcal
