// How the CLI shows an Evaluation: the JSON object of `evaluate --json` (keys in the documented
// order, then the program and K), the readable table, and the explanation of a rank-deficient or
// ill-conditioned program.
#pragma once
#include <ostream>
#include <string>

#include "experiments/cli/json_output.hpp"
#include "numeric/criteria/evaluation.hpp"

namespace scalcal::cli {

Json evaluation_json(const Evaluation& ev);
// The same with `program` ([[x, y, z], ...]) and `K` (9 x 9) after the documented keys.
Json evaluation_json(const Evaluation& ev, const Program& program);
void print_evaluation(std::ostream& out, const std::string& name, const Evaluation& ev);

// "rank 5 of 9; not identifiable: bias_z, scale_z, nonorth_yz, nonorth_zx"
std::string rank_deficiency(const Evaluation& ev);

// Above this condition number of H^T H the CLI warns and names the weakest combination.
inline constexpr double kIllConditioned = 1e10;
std::string ill_conditioning(const Evaluation& ev);

}  // namespace scalcal::cli
