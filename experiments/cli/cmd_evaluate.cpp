// `scalcal evaluate PROGRAM [--region SPEC]... [--out FILE] [--json]`: the criteria of one program,
// as the paper compares them; --out writes the program itself as CSV (any catalogue name becomes a
// file). With --region, positions outside the bench's region are refused, and each criterion gets
// its efficiency against the region's limit.
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/evaluate_report.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/program/catalogue.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  std::string program, out, model = "paper9";
  std::vector<std::string> regions;
  bool json = false;
};

int run(const Options& o) {
  return print_report(evaluate_report({o.program, resolve_program(o.program), model_of(o.model), o.regions, o.out}),
                      o.json);
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_positional(app, "PROGRAM", o->program, "a catalogue name (scalcal catalogue) or a CSV file (x,y,z or alpha1_deg,alpha2_deg)");
  add_region_option(app, o->regions);
  add_model(app, o->model);
  add_text(app, "--out", o->out, "FILE", {"also write the program as CSV x,y,z,alpha1_deg,alpha2_deg", "file path"});
  add_switch(app, "--json", o->json, "print one JSON object (the criteria, the program and K)");
  return [o] { return run(*o); };
}

const Registration reg({"evaluate", "evaluate PROGRAM [--model NAME] [--region SPEC]... [--out FILE] [--json]",
                        "criteria D, A, E, S, the RMS errors theta and K of a catalogue program or CSV file", 10,
                        setup});

}  // namespace
}  // namespace scalcal::cli
