// `scalcal optimize --positions N --criterion D|A|E|S [--region SPEC]... [--starts K] [--seed S]
// [--threads T] [--digits P] [--local auto|ipopt] [--out FILE] [--json]`: the optimal program by a
// multistart (Riemannian Newton for D and A, confirmed by Ipopt; Ipopt for E and S), optionally
// polished to P digits; with --digits, --out and the JSON program are the polished program. On a
// restricted region: exchange on the region's candidates, then Ipopt inside the region
// (numeric/region/region_synthesis.hpp), judged against the region's limit.
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>

#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/polish/polish.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/region/region_synthesis.hpp"
#include "numeric/synthesis/multistart.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  SynthesisOptions synthesis;
  std::string criterion = "D", local = "auto", out, model = "paper9";
  std::vector<std::string> regions;
  int digits = 0;
  bool json = false;
};

int run(Options& o) {
  SynthesisOptions& opt = o.synthesis;
  opt.criterion = criterion_of(o.criterion);
  opt.local = o.local == "ipopt" ? LocalSolver::Ipopt : LocalSolver::Automatic;
  opt.model = model_of(o.model);
  const bool paper9 = opt.model == ModelKind::paper9;
  require_positions("optimize", opt.positions, opt.model);
  if (!paper9 && (!o.regions.empty() || o.digits > 0))
    throw UsageError("optimize: --region and --digits work with the paper9 model only (got --model " + o.model + ")");
  if (progress_enabled())
    opt.progress = [](int done, int total) { std::cerr << "\rstart " << done << "/" << total << std::flush; };
  const std::optional<Region> region =
      o.regions.empty() ? std::nullopt : std::optional<Region>(resolve_region(o.regions, "optimize"));
  const bool restricted = region && !region->is_sphere();
  if (restricted && o.digits > 0)
    throw InputError("--digits", 0, "the polish solves the unconstrained optimality conditions; it cannot keep "
                                    "positions inside --region " + region->text());
  const SynthesisResult r = restricted ? synthesize_on_region(opt, *region) : synthesize(opt);
  if (opt.progress) std::cerr << "\n";
  if (!r.summary.converged())
    std::cerr << "scalcal optimize: warning: " << r.summary.message << " (" << r.local_solver << " multistart)\n";
  std::optional<PolishResult> polished;
  if (o.digits > 0) {
    if (opt.progress) std::cerr << "polishing at " << o.digits << " digits\n";
    polished = polish(r.program, opt.criterion, PolishOptions{o.digits, 40});
    if (!polished->converged())
      std::cerr << "scalcal optimize: warning: the polish did not converge (residual " << polished->residual
                << "); value_digits keeps " << polished->digits << " digits\n";
  }
  // The polished program is the better one (its rounding to double is as close to the optimum as
  // double allows): it is the one written and printed.
  const Program& best = polished ? polished->program : r.program;
  if (!o.out.empty()) write_program_file(o.out, best, region ? region_columns(*region, best) : std::vector<ExtraColumn>{});
  std::optional<double> limit;
  if (!paper9) {
    if (const auto l = stated_limit(opt.model, criterion_name(opt.criterion))) limit = l->value;
  } else if (region) {
    if (opt.progress) std::cerr << "the " << criterion_name(opt.criterion) << " limit on " << region->text() << "\n";
    limit = limit_value(opt.criterion, *region);
  }
  if (o.json) {
    Json j{{"criterion", std::string(criterion_name(opt.criterion))},
           {"positions", opt.positions},
           {"value", r.value},
           {"program", program_json(best)},
           {"starts", r.starts},
           {"hits", r.hits},
           {"distinct", r.distinct},
           {"seconds", r.seconds},
           {"local_solver", r.local_solver},
           {"confirmed", r.summary.converged()}};
    if (!paper9) {
      j["model"] = std::string(model_name(opt.model));
      if (limit) {
        j["limit"] = *limit;
        j["efficiency"] = efficiency(opt.criterion, *limit, r.value, model_parameters(opt.model));
      }
    } else if (limit) {
      j["region"] = region->text();
      j["limit"] = *limit;
      j["efficiency"] = efficiency(opt.criterion, *limit, r.value);
    }
    if (polished) {
      j["value_digits"] = polished->value_digits;
      j["residual"] = polished->residual;
      j["converged"] = polished->converged();
      j["iterations"] = polished->summary.iterations;
    }
    print_json(j);
  } else {
    std::cout << criterion_name(opt.criterion) << " = " << std::setprecision(15) << r.value
              << "  (N = " << opt.positions << ", " << r.hits << " of " << r.starts << " starts reached it, "
              << r.distinct << (r.distinct == 1 ? " program" : " distinct programs") << " up to symmetry, "
              << std::setprecision(3) << r.seconds << " s)\n";
    if (limit && !paper9)
      std::cout << "model " << model_name(opt.model) << ": limit " << std::setprecision(10) << *limit
                << ", efficiency " << std::setprecision(9)
                << efficiency(opt.criterion, *limit, r.value, model_parameters(opt.model))
                << " (limit / value; D as its " << model_parameters(opt.model) << "th root)\n";
    else if (limit)
      std::cout << "on " << region->text() << ": limit " << std::setprecision(10) << *limit << ", efficiency "
                << std::setprecision(9) << efficiency(opt.criterion, *limit, r.value)
                << " (limit / value; D as its 9th root)\n";
    if (polished)
      std::cout << criterion_name(opt.criterion) << " = " << polished->value_digits << "  (" << polished->digits
                << " digits, residual " << std::setprecision(3) << polished->residual << ", "
                << polished->summary.iterations << " Newton steps)\n";
  }
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_integer(app, "--positions", o->synthesis.positions, 3, 1000,
              {"number of positions N (at least the model's number of parameters)", "positions", kRequired});
  add_criterion(app, o->criterion);
  add_model(app, o->model);
  add_starts(app, o->synthesis.starts);
  add_region_option(app, o->regions);
  add_seed(app, o->synthesis.seed);
  add_threads(app, o->synthesis.threads);
  add_integer(app, "--digits", o->digits, 1, 1000,
              {"polish the optimum to this many digits in MPFR", "significant digits", "none (no polish)"});
  add_choice(app, "--local", o->local, {"auto", "ipopt"},
             {"local solver: auto = Newton for D and A, Ipopt for E and S; ipopt = Ipopt for all"});
  add_text(app, "--out", o->out, "FILE",
           {"write the program (the polished one with --digits) as CSV x,y,z,alpha1_deg,alpha2_deg", "file path"});
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"optimize",
                        "optimize --positions N --criterion D|A|E|S [--model NAME] [--region SPEC]... [--starts K] [--seed S] "
                        "[--threads T] [--digits P] [--local auto|ipopt] [--out FILE] [--json]",
                        "the optimal program for a criterion (Newton/Ipopt multistart, optional high-precision polish)",
                        40, setup});

}  // namespace
}  // namespace scalcal::cli
