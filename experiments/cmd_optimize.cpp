// `scalcal optimize --positions N --criterion D|A|E|S [--starts K] [--seed S] [--digits P]
// [--local auto|ipopt] [--out FILE] [--json]`: the optimal program by a multistart (Riemannian
// Newton for D and A, confirmed by Ipopt; Ipopt for E and S), optionally polished to P digits.
#include <iomanip>
#include <iostream>

#include "experiments/command.hpp"
#include "experiments/json.hpp"
#include "experiments/synthesis_cli.hpp"
#include <optional>

#include "numeric/polish/polish.hpp"
#include "numeric/synthesis/multistart.hpp"

namespace scalcal::cli {
namespace {

int run(Args& args) {
  SynthesisOptions opt;
  opt.positions = static_cast<int>(args.integer("positions", -1, 9, 1000));
  if (opt.positions < 0) throw UsageError("--positions N is required");
  opt.criterion = criterion_option(args, "D");
  opt.starts = static_cast<int>(args.integer("starts", 0, 1, 1000000));
  opt.seed = static_cast<std::uint64_t>(args.integer("seed", 1, 0, (1LL << 62)));
  opt.threads = static_cast<int>(args.integer("threads", 0, 0, 256));
  const int digits = static_cast<int>(args.integer("digits", 0, 1, 1000));
  const std::string local = args.text("local", "auto");
  if (local != "auto" && local != "ipopt") throw UsageError("--local must be auto or ipopt, got '" + local + "'");
  opt.local = local == "ipopt" ? LocalSolver::Ipopt : LocalSolver::Automatic;
  const auto out_file = args.value("out");
  const bool json = args.flag("json");
  if (!args.positionals().empty()) throw UsageError("unexpected positional argument");
  if (progress_enabled())
    opt.progress = [](int done, int total) { std::cerr << "\rstart " << done << "/" << total << std::flush; };
  const SynthesisResult r = synthesize(opt);
  if (opt.progress) std::cerr << "\n";
  if (!r.summary.converged())
    std::cerr << "scalcal optimize: warning: " << r.summary.message << " (" << r.local_solver << " multistart)\n";
  std::optional<PolishResult> polished;
  if (digits > 0) {
    if (opt.progress) std::cerr << "polishing at " << digits << " digits\n";
    polished = polish(r.program, opt.criterion, PolishOptions{digits, 40});
    if (!polished->converged())
      std::cerr << "scalcal optimize: warning: the polish did not converge (residual " << polished->residual << "); value_digits keeps "
                << polished->digits << " digits\n";
  }
  if (out_file) write_program_file(*out_file, r.program);
  if (json) {
    Json j = Json::object();
    j.set("criterion", std::string(criterion_name(opt.criterion)));
    j.set("positions", opt.positions);
    j.set("value", r.value);
    j.set("program", program_json(r.program));
    j.set("starts", r.starts);
    j.set("hits", r.hits);
    j.set("distinct", r.distinct);
    j.set("seconds", r.seconds);
    j.set("local_solver", r.local_solver);
    j.set("confirmed", r.summary.converged());
    if (polished) {
      j.set("value_digits", polished->value_digits);
      j.set("residual", polished->residual);
    }
    j.dump(std::cout);
    std::cout << "\n";
  } else {
    std::cout << criterion_name(opt.criterion) << " = " << std::setprecision(15) << r.value << "  (N = " << opt.positions
              << ", " << r.hits << " of " << r.starts << " starts reached it, " << r.distinct
              << (r.distinct == 1 ? " program" : " distinct programs") << " up to symmetry, " << std::setprecision(3) << r.seconds
              << " s)\n";
    if (polished)
      std::cout << criterion_name(opt.criterion) << " = " << polished->value_digits << "  (" << polished->digits
                << " digits, residual " << std::setprecision(3) << polished->residual << ", " << polished->summary.iterations
                << " Newton steps)\n";
  }
  return 0;
}

const Registration reg({"optimize",
                        "optimize --positions N --criterion D|A|E|S [--starts K] [--seed S] [--digits P] [--local auto|ipopt] [--out FILE] [--json]",
                        "the optimal program for a criterion (Newton/Ipopt multistart, optional high-precision polish)", 40, run});

}  // namespace
}  // namespace scalcal::cli
