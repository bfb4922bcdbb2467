// How the CLI shows an Evaluation as text: the table of `scalcal evaluate` (its JSON form is
// commands/core/evaluation_json.hpp).
#pragma once
#include <ostream>
#include <string>

#include "commands/core/evaluation_json.hpp"
#include "experiments/cli/json_output.hpp"
#include "numeric/criteria/identifiability.hpp"

namespace scalcal::cli {

using commands::evaluation_json;
void print_evaluation(std::ostream& out, const std::string& name, const ModelEvaluation& ev);
void print_evaluation(std::ostream& out, const std::string& name, const Evaluation& ev);

}  // namespace scalcal::cli
