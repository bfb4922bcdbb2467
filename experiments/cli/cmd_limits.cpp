// `scalcal limits [--region SPEC]... [--json]`: the infimum of each normalised criterion over all
// measures on the sphere, derived symbolically (symbolic/limits.hpp), with the moments of an
// optimal measure; on a restricted region, an optimal measure found numerically and a lower bound
// certified by weak duality over the whole region (numeric/region/region_limit.hpp).
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/limits_report.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  std::vector<std::string> regions;
  std::string model = "paper9";
  bool json = false;
};

int run(const Options& o) { return print_report(limits_report(model_of(o.model), o.regions), o.json); }

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_region_option(app, o->regions);
  add_model(app, o->model);
  add_switch(app, "--json", o->json, "print one JSON object keyed by criterion");
  return [o] { return run(*o); };
}

const Registration reg({"limits", "limits [--model NAME] [--region SPEC]... [--json]",
                        "N -> infinity limits of the normalised D, A, E, S criteria: exact on the sphere, certified "
                        "bounds on a region",
                        61, setup});

}  // namespace
}  // namespace scalcal::cli
