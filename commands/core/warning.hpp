// A warning as data: what it concerns (a file, an option, a stage of the work) and the sentence a
// person reads. The library collects them in its results; the CLI prints each as one stderr line
// ("scalcal COMMAND: SUBJECT: warning: MESSAGE"), the Python module passes each to warnings.warn.
#pragma once
#include <string>
#include <vector>

namespace scalcal::commands {

struct Warning {
  std::string subject;  // e.g. the file name; empty when the warning concerns the whole command
  std::string message;
};

using Warnings = std::vector<Warning>;

}  // namespace scalcal::commands
