// How the CLI shows an Evaluation: the JSON object of `evaluate --json` (keys in the documented
// order), the readable table, and the explanation of a rank-deficient or ill-conditioned program.
#pragma once
#include <ostream>
#include <string>

#include "experiments/json.hpp"
#include "numeric/criteria/evaluation.hpp"

namespace scalcal::cli {

Json evaluation_json(const Evaluation& ev);
void print_evaluation(std::ostream& out, const std::string& name, const Evaluation& ev);

// "rank 5 of 9; not identifiable: bias_z, scale_z, nonorth_yz, nonorth_zx"
std::string rank_deficiency(const Evaluation& ev);

// Above this condition number of H^T H the CLI warns and names the weakest combination.
inline constexpr double kIllConditioned = 1e10;
std::string ill_conditioning(const Evaluation& ev);

}  // namespace scalcal::cli
