// How long work reports where it is: the library calls Progress between units of work (a start of
// the multistart, a stage of the reproduction), from one thread at a time. The CLI draws it on a
// terminal's stderr; the Python module checks for Ctrl-C there. A callback may throw to stop the
// work: the exception leaves the command as it is.
#pragma once
#include <functional>
#include <string_view>

namespace scalcal::commands {

// stage: what is running ("starts", "limit D on cap:30"); done of total units (total 0: unknown).
using Progress = std::function<void(std::string_view stage, int done, int total)>;

}  // namespace scalcal::commands
