// `scalcal reproduce` as a command: its option table (shared by the CLI and the Python module) and
// the pipeline's options and summary from and to the commands' forms. Its result is the folder it
// writes (REPORT.md, the figures and their data): the one command whose work is files.
#pragma once
#include "commands/core/json.hpp"
#include "commands/core/values.hpp"
#include "experiments/reproduce/pipeline.hpp"

namespace scalcal::reproduce {

// [--out DIR] [--quick] [--threads T] [--quiet]
const commands::CommandTable& reproduce_table();
Options reproduce_options(const commands::Values& values);
commands::Json to_json(const RunSummary& summary);  // {"report": path, "seconds": s}

}  // namespace scalcal::reproduce
