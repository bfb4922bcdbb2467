// The JSON form of an evaluation, in the documented key order: [model, parameters,] positions, rank,
// condition, every registered criterion by name, the thetas of the model's groups, every criterion's
// raw value by its raw key (det_K, ...), unidentifiable; with the program, also `program` and `K`.
#pragma once
#include "commands/core/json.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/criteria/model_evaluation.hpp"

namespace scalcal::commands {

Json evaluation_json(const ModelEvaluation& ev);
Json evaluation_json(const ModelEvaluation& ev, const Program& program);
Json evaluation_json(const Evaluation& ev);
Json evaluation_json(const Evaluation& ev, const Program& program);

// Each registered criterion's normalised value under its name, in the registry's order, then the
// thetas of the groups the model has: the criteria part of every report that summarises a program.
void add_criteria(Json& j, const ModelEvaluation& ev);

}  // namespace scalcal::commands
