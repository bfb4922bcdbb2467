// `scalcal evaluate PROGRAM [--json]`: the criteria of one program, as the paper compares them.
#include <iostream>

#include "experiments/command.hpp"
#include "experiments/evaluation_report.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::cli {
namespace {

int run(Args& args) {
  const bool json = args.flag("json");
  const auto pos = args.positionals();
  if (pos.size() != 1) throw UsageError("expected exactly one PROGRAM (a catalogue name or a CSV file)");
  const Program program = resolve_program(pos[0]);
  const Evaluation ev = evaluate(program);
  if (!ev.full_rank()) throw InputError(pos[0], 0, rank_deficiency(ev));
  if (ev.condition > kIllConditioned) std::cerr << "scalcal evaluate: " << pos[0] << ": warning: " << ill_conditioning(ev) << "\n";
  if (json) {
    evaluation_json(ev).dump(std::cout);
    std::cout << "\n";
  } else {
    print_evaluation(std::cout, pos[0], ev);
  }
  return 0;
}

const Registration reg({"evaluate", "evaluate PROGRAM [--json]",
                        "criteria D, A, E, S, the RMS errors theta and K of a catalogue program or CSV file",
                        10, run});

}  // namespace
}  // namespace scalcal::cli
