// Why a program cannot be used as it is: the parameters a rank-deficient program cannot identify,
// and the combination an ill-conditioned one determines poorly. The library explains; it never
// regularises. Every front end (CLI, reproduce, bindings) prints these same sentences.
#pragma once
#include <string>

#include "numeric/criteria/model_evaluation.hpp"

namespace scalcal {

// Above this condition number of H^T H a program is reported as ill-conditioned: in double, the
// estimate then loses more than 10 of its 16 digits to the design alone.
inline constexpr double kIllConditioned = 1e10;

// "rank-deficient program: rank 5 of 9; not identifiable: bias_z, scale_z, nonorth_yz, nonorth_zx"
std::string rank_deficiency(const ModelEvaluation& ev);
std::string rank_deficiency(const Evaluation& ev);

// "ill-conditioned program (condition 3.2e+12): the combination poorly determined is mostly scale_z, ..."
std::string ill_conditioning(const ModelEvaluation& ev);
std::string ill_conditioning(const Evaluation& ev);

}  // namespace scalcal
