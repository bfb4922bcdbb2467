#include "experiments/cli/synthesis_cli.hpp"

#include <stdexcept>
#include <string>

#include "experiments/cli/command.hpp"
#include "experiments/cli/options.hpp"

namespace scalcal::cli {

std::vector<std::string> criterion_names() {
  std::vector<std::string> names;
  for (auto c : kCriteria) names.emplace_back(criterion_name(c));
  return names;
}

std::vector<std::string> model_names() {
  std::vector<std::string> names;
  for (int i = 0; i < kModelCount; ++i) names.emplace_back(model_name(ModelKind(i)));
  return names;
}

std::vector<std::string> local_solver_names() { return {"auto", "newton", "lbfgs", "ipopt"}; }

LocalSolver local_solver_of(const std::string& name) {
  return name == "newton" ? LocalSolver::Newton
         : name == "lbfgs" ? LocalSolver::Lbfgs
         : name == "ipopt" ? LocalSolver::Ipopt
                           : LocalSolver::Automatic;
}

void add_criterion(CLI::App& app, std::string& target, const std::string& fallback_text) {
  add_choice(app, "--criterion", target, criterion_names(),
             {"the criterion: D = N^9 det K, A = N trace K, E = N lambda_max K, S = N max K(r,r)", "none",
              fallback_text});
}

CriterionKind criterion_of(const std::string& name) {
  const auto c = parse_criterion(name);
  if (!c) throw std::logic_error("unchecked criterion '" + name + "'");
  return *c;
}

void add_model(CLI::App& app, std::string& target) {
  add_choice(app, "--model", target, model_names(),
             {"the calibration model: paper9 (the paper's 9 parameters), axis6 (bias and scale factor), bias3 "
              "(offsets only), cubic12 (paper9 plus x^3, y^3, z^3)"});
}

ModelKind model_of(const std::string& name) {
  if (name.empty()) return ModelKind::paper9;
  const auto m = parse_model(name);
  if (!m) throw std::logic_error("unchecked model '" + name + "'");
  return *m;
}

void require_positions(const std::string& command, int positions, ModelKind model) {
  if (positions < model_parameters(model))
    throw UsageError(command + ": --positions " + std::to_string(positions) + " is below the " +
                     std::to_string(model_parameters(model)) + " parameters of --model " +
                     std::string(model_name(model)));
}

void add_seed(CLI::App& app, std::uint64_t& seed) {
  add_integer(app, "--seed", seed, kSeeds.lo, kSeeds.hi, {"seed of every random choice (the same seed, the same answer)"});
}

void add_starts(CLI::App& app, int& starts) {
  add_integer(app, "--starts", starts, kStarts.lo, kStarts.hi,
              {"random starts of the multistart", "starts", "adaptive: batches of 8 until 8 consecutive starts hit the best, capped at the criterion's count; 8 on a restricted --region; K forces K"});
}

void add_threads(CLI::App& app, int& threads) {
  add_integer(app, "--threads", threads, kThreads.lo, kThreads.hi, {"worker threads or processes", "threads", "0 = all cores"});
}

}  // namespace scalcal::cli
