// `scalcal optimize --positions N|--from PROGRAM --criterion D|A|E|S [--region SPEC]... [--starts K] [--seed S]
// [--threads T] [--digits P] [--local auto|ipopt] [--out FILE] [--json]`: the optimal program by a
// multistart (Riemannian Newton for D and A, confirmed by Ipopt; Ipopt for E and S), optionally
// polished to P digits; with --digits, --out and the JSON program are the polished program. On a
// restricted region: exchange on the region's candidates, then Ipopt inside the region
// (numeric/region/region_synthesis.hpp), judged against the region's limit.
#include <iostream>
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/optimize_report.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/catalogue.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  SynthesisOptions synthesis;
  std::string criterion = "D", local = "auto", out, model = "paper9", from;
  std::vector<std::string> regions;
  int digits = 0;
  bool json = false;
};

int run(Options& o) {
  if (!o.from.empty()) {
    Program start = resolve_program(o.from);
    if (o.synthesis.positions != 0 && o.synthesis.positions != start.size())
      throw UsageError("--positions " + std::to_string(o.synthesis.positions) + " but --from " + display_name(o.from) +
                       " has " + std::to_string(start.size()) + " positions");
    if (start.size() < kOptimizePositions.lo || start.size() > kOptimizePositions.hi)
      throw UsageError("--from " + display_name(o.from) + " has " + std::to_string(start.size()) + " positions; optimize takes " +
                       std::to_string(kOptimizePositions.lo) + ".." + std::to_string(kOptimizePositions.hi));
    if (!o.regions.empty()) throw UsageError("--from starts the search on the sphere; it does not take --region");
    o.synthesis.positions = start.size();
    o.synthesis.first_start = std::move(start);
  } else if (o.synthesis.positions == 0) {
    throw UsageError("--positions N is required (or --from PROGRAM, whose size it takes)");
  }
  OptimizeRequest q{o.synthesis, o.regions, o.digits, o.out};
  q.synthesis.criterion = criterion_of(o.criterion);
  q.synthesis.local = local_solver_of(o.local);
  q.synthesis.model = model_of(o.model);
  if (progress_enabled())
    q.synthesis.progress = [](int done, int total) { std::cerr << "\rstart " << done << "/" << total << std::flush; };
  return print_report(optimize_report(q), o.json);
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  o->synthesis.positions = 0;  // unset: --from gives it, or it is required
  add_integer(app, "--positions", o->synthesis.positions, kOptimizePositions.lo, kOptimizePositions.hi,
              {"number of positions N (at least the model's number of parameters)", "positions",
               "required, unless --from gives it"});
  add_text(app, "--from", o->from, "PROGRAM",
           {"start 0 of the multistart is this program (a catalogue name, a family member such as jig:cuboctahedron, "
            "or a CSV file); N is its size",
            "catalogue name or file path"});
  add_criterion(app, o->criterion);
  add_model(app, o->model);
  add_starts(app, o->synthesis.starts);
  add_region_option(app, o->regions);
  add_seed(app, o->synthesis.seed);
  add_threads(app, o->synthesis.threads);
  add_integer(app, "--digits", o->digits, kPolishDigits.lo, kPolishDigits.hi,
              {"polish the optimum to this many digits in MPFR", "significant digits", "none (no polish)"});
  add_choice(app, "--local", o->local, local_solver_names(),
             {"local solver: auto = Riemannian Newton for D and A below N = 40, L-BFGS from N = 40, Ipopt for E "
              "and S (E warm-started by A's solver); newton, lbfgs = that solver for D, A and E's warm start; "
              "ipopt = Ipopt for all"});
  add_text(app, "--out", o->out, "FILE",
           {"write the program (the polished one with --digits) as CSV x,y,z,alpha1_deg,alpha2_deg", "file path"});
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"optimize",
                        "optimize --positions N|--from PROGRAM --criterion D|A|E|S [--model NAME] [--region SPEC]... [--starts K] [--seed S] "
                        "[--threads T] [--digits P] [--local auto|ipopt] [--out FILE] [--json]",
                        "the optimal program for a criterion (Newton/Ipopt multistart, optional high-precision polish)",
                        40, setup});

}  // namespace
}  // namespace scalcal::cli
