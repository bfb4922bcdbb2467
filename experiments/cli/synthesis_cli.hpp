// Options shared by the synthesis subcommands (optimize, random, sweep, polish): the criterion, the
// seed, the number of starts and of threads, with one text, range and help line everywhere.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "experiments/cli/options.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/synthesis/local_result.hpp"

namespace scalcal::cli {

void add_criterion(CLI::App& app, std::string& target, const std::string& fallback_text = "");
CriterionKind criterion_of(const std::string& name);  // a name add_criterion has checked

// --model NAME (default paper9), one of the registered models.
void add_model(CLI::App& app, std::string& target);
ModelKind model_of(const std::string& name);  // a name add_model has checked
// UsageError from `command` unless positions >= the model's number of parameters.
void require_positions(const std::string& command, int positions, ModelKind model);

inline constexpr IntegerRange kSeeds{0, 1LL << 62}, kStarts{1, 1000000}, kThreads{0, 256};

// The names --criterion and --model accept, in the registries' order.
std::vector<std::string> criterion_names();
std::vector<std::string> model_names();

// --local auto|newton|lbfgs|ipopt: the multistart's local solver.
std::vector<std::string> local_solver_names();
LocalSolver local_solver_of(const std::string& name);  // a name of local_solver_names()

void add_seed(CLI::App& app, std::uint64_t& seed);
void add_starts(CLI::App& app, int& starts);
void add_threads(CLI::App& app, int& threads);

}  // namespace scalcal::cli
