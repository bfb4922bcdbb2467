// One local optimisation of a program by Ipopt, for any criterion and model (the building block of
// the multistart for the nonsmooth forms, and the confirmation of Newton's best). Positions are unit
// vectors held by norm constraints, so there are no angle poles.
#pragma once
#include <functional>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/synthesis/ipopt_problems.hpp"
#include "numeric/synthesis/local_result.hpp"
#include "numeric/synthesis/position_bounds.hpp"

namespace scalcal {

// The Ipopt run itself (ipopt_local.cpp): `value_of` gives the normalised criterion of a program;
// `bounds` (one per position, or null: all free) keeps positions inside a restricted bench.
LocalResult run_ipopt(const SmoothProblem& problem, const Program& start, const LocalOptions& options,
                      const std::function<double(const Program&)>& value_of, const PositionBounds* bounds = nullptr);

template <Criterion C, class Model = Paper9Model>
LocalResult optimize_with_ipopt(const Program& start, const LocalOptions& options = {},
                                const PositionBounds* bounds = nullptr) {
  const std::unique_ptr<SmoothProblem> problem = make_problem<C, Model>(start.size());
  return run_ipopt(*problem, start, options, [](const Program& p) { return criterion_value<C, Model>(p); }, bounds);
}

}  // namespace scalcal
