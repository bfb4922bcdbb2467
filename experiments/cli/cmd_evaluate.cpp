// `scalcal evaluate PROGRAM [--out FILE] [--json]`: the criteria of one program, as the paper
// compares them; --out writes the program itself as CSV (any catalogue name becomes a file).
#include <iostream>
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/evaluation_report.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/output_file.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/catalogue.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  std::string program, out;
  bool json = false;
};

int run(const Options& o) {
  const Program program = resolve_program(o.program);
  const Evaluation ev = evaluate(program);
  if (!ev.full_rank()) throw InputError(o.program, 0, rank_deficiency(ev));
  if (ev.condition > kIllConditioned)
    std::cerr << "scalcal evaluate: " << o.program << ": warning: " << ill_conditioning(ev) << "\n";
  if (!o.out.empty()) write_program_file(o.out, program);
  if (o.json)
    print_json(evaluation_json(ev, program));
  else
    print_evaluation(std::cout, o.program, ev);
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_positional(app, "PROGRAM", o->program, "a catalogue name (scalcal catalogue) or a CSV file (x,y,z or alpha1_deg,alpha2_deg)");
  add_text(app, "--out", o->out, "FILE", {"also write the program as CSV x,y,z,alpha1_deg,alpha2_deg", "file path"});
  add_switch(app, "--json", o->json, "print one JSON object (the criteria, the program and K)");
  return [o] { return run(*o); };
}

const Registration reg({"evaluate", "evaluate PROGRAM [--out FILE] [--json]",
                        "criteria D, A, E, S, the RMS errors theta and K of a catalogue program or CSV file", 10,
                        setup});

}  // namespace
}  // namespace scalcal::cli
