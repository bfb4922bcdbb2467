// `scalcal random --positions N --count R [--seed S] [--criterion C] [--json]`: the best of R
// uniform random programs (the paper's dashed line, R = 100000), on all cores.
#include <iomanip>
#include <iostream>

#include "experiments/command.hpp"
#include "experiments/json.hpp"
#include "experiments/synthesis_cli.hpp"
#include "numeric/synthesis/multistart.hpp"
#include "numeric/synthesis/random_search.hpp"

namespace scalcal::cli {
namespace {

int run(Args& args) {
  const int n = static_cast<int>(args.integer("positions", -1, 9, 100000));
  if (n < 0) throw UsageError("--positions N is required");
  const long long count = args.integer("count", -1, 1, 1LL << 50);
  if (count < 0) throw UsageError("--count R is required");
  const auto seed = static_cast<std::uint64_t>(args.integer("seed", 1, 0, 1LL << 62));
  const CriterionKind c = criterion_option(args, "D");
  const int threads = static_cast<int>(args.integer("threads", 0, 0, 256));
  const bool json = args.flag("json");
  if (!args.positionals().empty()) throw UsageError("unexpected positional argument");
  const RandomSearchResult r = random_search(n, count, c, seed, threads);
  if (json) {
    Json j = Json::object();
    j.set("best", r.best);
    j.set("count", r.count);
    j.set("program", program_json(r.program));
    j.set("seconds", r.seconds);
    j.dump(std::cout);
    std::cout << "\n";
  } else {
    std::cout << "best " << criterion_name(c) << " = " << std::setprecision(12) << r.best << " of " << r.count
              << " random programs of " << n << " positions (" << std::setprecision(3) << r.seconds << " s, "
              << r.count / r.seconds / 1e6 << " M programs/s)\n";
  }
  return 0;
}

const Registration reg({"random", "random --positions N --count R [--seed S] [--criterion C] [--json]",
                        "the best of R uniform random programs (the paper's dashed line), on all cores", 41, run});

}  // namespace
}  // namespace scalcal::cli
