// How the CLI shows an Evaluation: the JSON object of `evaluate --json` (keys in the documented
// order, then the program and K) and the readable table.
#pragma once
#include <ostream>
#include <string>

#include "experiments/cli/json_output.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/criteria/model_evaluation.hpp"

namespace scalcal::cli {

Json evaluation_json(const ModelEvaluation& ev);
Json evaluation_json(const ModelEvaluation& ev, const Program& program);
void print_evaluation(std::ostream& out, const std::string& name, const ModelEvaluation& ev);
Json evaluation_json(const Evaluation& ev);
// The same with `program` ([[x, y, z], ...]) and `K` (9 x 9) after the documented keys.
Json evaluation_json(const Evaluation& ev, const Program& program);
void print_evaluation(std::ostream& out, const std::string& name, const Evaluation& ev);

}  // namespace scalcal::cli
