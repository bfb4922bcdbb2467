// A build with GiNaC (build_features.hpp): every command, the families' program names from symbolic/.
#include "commands/core/build_features.hpp"
#include "symbolic/family.hpp"

namespace scalcal::commands {

bool with_ginac() { return true; }

void register_family_programs() { symbolic::register_family_programs(); }

}  // namespace scalcal::commands
