// One local optimisation of a program by Ipopt, for any criterion and model (the building block of
// the multistart for the nonsmooth forms, and the confirmation of Newton's best). Positions are unit
// vectors held by norm constraints, so there are no angle poles.
#pragma once
#include <functional>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/synthesis/ipopt_problems.hpp"
#include "numeric/synthesis/local_result.hpp"

namespace scalcal {

// The Ipopt run itself (ipopt_local.cpp): `value_of` gives the normalised criterion of a program.
LocalResult run_ipopt(const SmoothProblem& problem, const Program& start, const LocalOptions& options,
                      const std::function<double(const Program&)>& value_of);

template <Criterion C, class Model = Paper9Model>
LocalResult optimize_with_ipopt(const Program& start, const LocalOptions& options = {}) {
  const std::unique_ptr<SmoothProblem> problem = make_problem<C, Model>(start.size());
  return run_ipopt(*problem, start, options, [](const Program& p) { return criterion_value<C, Model>(p); });
}

}  // namespace scalcal
