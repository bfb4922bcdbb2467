// The programs every figure draws from, computed once per run: the analytic classes of the paper's
// Fig. 4, its Tables 1-3, the best random programs per N and the optimised programs per criterion.
#pragma once
#include "experiments/reproduce/context.hpp"

namespace scalcal::reproduce {

void compute_analytic(Context& ctx);
void compute_random(Context& ctx);
void compute_optimised(Context& ctx);

}  // namespace scalcal::reproduce
