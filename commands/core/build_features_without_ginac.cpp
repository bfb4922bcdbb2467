// A build without GiNaC (-DSCALCAL_WITH_GINAC=OFF, build_features.hpp): the families are GiNaC expressions
// (symbolic/families/), so their program names are refused in one line that says why; the paper's programs,
// whose names numeric owns, and program files are unchanged.
#include <optional>
#include <string>

#include "commands/core/build_features.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/program_names.hpp"

namespace scalcal::commands {

bool with_ginac() { return false; }

void register_family_programs() {
  ProgramNames names;
  names.key = "family:jig";
  names.pattern = "jig:NAME";
  names.group = "jig";
  names.resolve = [](const std::string& name) -> std::optional<Program> {
    if (name.rfind("jig:", 0) != 0) return std::nullopt;
    throw InputError(name, 0,
                     "the printable jigs are families with exact face normals, which need GiNaC: this build was made "
                     "with -DSCALCAL_WITH_GINAC=OFF");
  };
  register_program_names(std::move(names));
}

}  // namespace scalcal::commands
