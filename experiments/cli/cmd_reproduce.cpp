// `scalcal reproduce [--out DIR] [--quick] [--threads T] [--quiet]`: regenerates the paper's figures and
// tables, and the new figures, into DIR (experiments/reproduce/pipeline.hpp does the work).
#include <iostream>

#include "experiments/cli/command.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/reproduce/command.hpp"
#include "experiments/reproduce/format.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::cli {
namespace {

int run(const commands::Values& v) {
  reproduce::RunSummary s;
  try {
    s = reproduce::run(reproduce::reproduce_options(v),
                       reproduce::progress_mode(v.flag("--quiet"), progress_enabled()));
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {  // the pipeline's files: the folder, a CSV, REPORT.md
    throw OutputError(e.what());
  }
  std::cout << "wrote " << s.report.string() << " and its figures in " << reproduce::decimal(s.seconds, 3) << " s\n";
  return 0;
}

const Registration reg(reproduce::reproduce_table(), run);

}  // namespace
}  // namespace scalcal::cli
