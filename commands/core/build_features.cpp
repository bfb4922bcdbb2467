// What a build without GiNaC lacks, named the same way by every front end (build_features.hpp).
#include "commands/core/build_features.hpp"

namespace scalcal::commands {

std::vector<LackingCommand> lacking_commands() {
  if (with_ginac()) return {};
  return {{"family", "the exact criteria of a family member, closed forms in its parameters"},
          {"jig", "a printable jig's limits, decided exactly from its face normals"}};
}

std::string lacking_message(const LackingCommand& command) {
  return "`" + command.name + "` (" + command.what + ") needs GiNaC: this build was made with -DSCALCAL_WITH_GINAC=OFF";
}

}  // namespace scalcal::commands
