// What this build holds: GiNaC's closed forms or not (-DSCALCAL_WITH_GINAC, docs/library.md). Without
// GiNaC the commands that are closed forms through and through (`family`, `jig`) are lacking, and so are
// the families' program names (the printable jigs, jig:NAME); the front ends name what is lacking in one
// line. build_features_with_ginac.cpp and build_features_without_ginac.cpp are the two builds' sides.
#pragma once
#include <string>
#include <vector>

namespace scalcal::commands {

// True when this build was made with GiNaC (-DSCALCAL_WITH_GINAC=ON, the default).
bool with_ginac();

struct LackingCommand {
  std::string name;  // "family"
  std::string what;  // what it gives, for the message: "the exact criteria of a family member"
};

// The commands this build lacks: none with GiNaC; without it `family` and `jig`.
std::vector<LackingCommand> lacking_commands();

// The one line a front end gives for a lacking command: "`family` (the exact criteria of a family member)
// needs GiNaC: this build was made with -DSCALCAL_WITH_GINAC=OFF".
std::string lacking_message(const LackingCommand& command);

// Registers the families' program names with numeric's registry (numeric/program/program_names.hpp); without
// GiNaC a jig:NAME program is refused with the same kind of line (InputError). Front ends call it once at
// start; idempotent.
void register_family_programs();

}  // namespace scalcal::commands
