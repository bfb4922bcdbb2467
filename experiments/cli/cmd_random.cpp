// `scalcal random --positions N --count R [--seed S] [--criterion C] [--model NAME] [--region SPEC]...
// [--threads T] [--json]`: the best of R uniform random programs (the paper's dashed line, R = 100000), on all
// cores; on a restricted region, uniform on it (numeric/region/region_sampler.hpp).
#include <iomanip>
#include <iostream>
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/region/region_sampler.hpp"
#include "numeric/synthesis/multistart.hpp"
#include "numeric/synthesis/random_search.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  int positions = 0, threads = 0;
  long long count = 0;
  std::uint64_t seed = 1;
  std::string criterion = "D", model = "paper9";
  std::vector<std::string> regions;
  bool json = false;
};

int run(const Options& o) {
  const CriterionKind c = criterion_of(o.criterion);
  const ModelKind model = model_of(o.model);
  require_positions("random", o.positions, model);
  PositionSampler sampler;
  std::string region_text;
  if (!o.regions.empty()) {
    const Region region = resolve_region(o.regions, "random");
    if (!region.is_sphere()) {
      sampler = region_sampler(region);
      region_text = region.text();
    }
  }
  const RandomSearchResult r = random_search(o.positions, o.count, c, o.seed, o.threads, sampler, model);
  if (o.json) {
    Json j{{"best", r.best}, {"count", r.count}, {"program", program_json(r.program)}, {"seconds", r.seconds}};
    if (!region_text.empty()) j["region"] = region_text;
    if (model != ModelKind::paper9) j["model"] = std::string(model_name(model));
    print_json(j);
  } else {
    std::cout << "best " << criterion_name(c) << " = " << std::setprecision(12) << r.best << " of " << r.count
              << " random programs of " << o.positions << " positions"
              << (model == ModelKind::paper9 ? "" : " (model " + std::string(model_name(model)) + ")") << (region_text.empty() ? "" : " on " + region_text)
              << " (" << std::setprecision(3) << r.seconds
              << " s, " << r.count / r.seconds / 1e6 << " M programs/s)\n";
  }
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_integer(app, "--positions", o->positions, 3, 100000,
              {"number of positions N (at least the model's number of parameters)", "positions", kRequired});
  add_integer(app, "--count", o->count, 1, 1000000000LL, {"random programs drawn", "programs", kRequired});
  add_seed(app, o->seed);
  add_criterion(app, o->criterion);
  add_model(app, o->model);
  add_region_option(app, o->regions);
  add_threads(app, o->threads);
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"random",
                        "random --positions N --count R [--seed S] [--criterion C] [--model NAME] [--region SPEC]... "
                        "[--threads T] [--json]",
                        "the best of R uniform random programs (the paper's dashed line), on all cores", 41, setup});

}  // namespace
}  // namespace scalcal::cli
