// `scalcal reproduce [--out DIR] [--quick] [--threads T] [--quiet]`: regenerates the paper's Figs. 4-9
// and Tables 1-3, and the new figures, into DIR (experiments/reproduce/pipeline.hpp does the work).
#include <iostream>
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "experiments/reproduce/format.hpp"
#include "experiments/reproduce/pipeline.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  std::string out = "results";
  reproduce::Options pipeline;
  bool quiet = false;
};

int run(Options& o) {
  o.pipeline.out = o.out;
  reproduce::RunSummary s;
  try {
    s = reproduce::run(o.pipeline, reproduce::progress_mode(o.quiet, progress_enabled()));
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {  // the pipeline's files: the folder, a CSV, REPORT.md
    throw OutputError(e.what());
  }
  std::cout << "wrote " << s.report.string() << " and its figures in " << reproduce::decimal(s.seconds, 3) << " s\n";
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_text(app, "--out", o->out, "DIR", {"folder for the figures, their data and REPORT.md", "folder path"});
  add_switch(app, "--quick", o->pipeline.quick, "small sweeps (2-4 optimiser starts, few N), as the tests run");
  add_threads(app, o->pipeline.threads);
  add_switch(app, "--quiet", o->quiet, "no progress on stderr (by default one line per stage, with the time left)");
  return [o] { return run(*o); };
}

const Registration reg({"reproduce", "reproduce [--out DIR] [--quick] [--threads T] [--quiet]",
                        "regenerate the paper's Figs. 4-9 and Tables 1-3 (PDF, PNG, SVG, CSV, REPORT.md)", 50, setup});

}  // namespace
}  // namespace scalcal::cli
