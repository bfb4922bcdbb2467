#include "experiments/cli/synthesis_cli.hpp"

#include <stdexcept>

#include "experiments/cli/options.hpp"

namespace scalcal::cli {

void add_criterion(CLI::App& app, std::string& target, const std::string& fallback_text) {
  add_choice(app, "--criterion", target, {"D", "A", "E", "S"},
             {"the criterion: D = N^9 det K, A = N trace K, E = N lambda_max K, S = N max K(r,r)", "none",
              fallback_text});
}

CriterionKind criterion_of(const std::string& name) {
  const auto c = parse_criterion(name);
  if (!c) throw std::logic_error("unchecked criterion '" + name + "'");
  return *c;
}

void add_seed(CLI::App& app, std::uint64_t& seed) {
  add_integer(app, "--seed", seed, 0, 1LL << 62, {"seed of every random choice (the same seed, the same answer)"});
}

void add_starts(CLI::App& app, int& starts) {
  add_integer(app, "--starts", starts, 1, 1000000,
              {"random starts of the multistart", "starts", "chosen to find the global optimum for N <= 30; 8 on a restricted --region"});
}

void add_threads(CLI::App& app, int& threads) {
  add_integer(app, "--threads", threads, 0, 256, {"worker threads or processes", "threads", "0 = all cores"});
}

}  // namespace scalcal::cli
