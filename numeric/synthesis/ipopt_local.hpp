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

// One Ipopt run of a criterion under the model (compiled once per model).
template <class Model>
LocalResult ipopt_local(const CriterionOps<Model>& criterion, const Program& start, const LocalOptions& options = {},
                        const PositionBounds* bounds = nullptr) {
  const std::unique_ptr<SmoothProblem> problem = make_problem<Model>(criterion, start.size());
  return run_ipopt(
      *problem, start, options, [&criterion](const Program& p) { return criterion_value(criterion, p); }, bounds);
}

template <Criterion C, class Model = Paper9Model>
LocalResult optimize_with_ipopt(const Program& start, const LocalOptions& options = {},
                                const PositionBounds* bounds = nullptr) {
  return ipopt_local<Model>(criterion_ops<C, Model>(), start, options, bounds);
}

#define SCALCAL_IPOPT_LOCAL_INSTANCES(prefix, M)                                                          \
  prefix template LocalResult ipopt_local<M>(const CriterionOps<M>&, const Program&, const LocalOptions&, \
                                             const PositionBounds*);
#define SCALCAL_EXTERN_IPOPT_LOCAL(M) SCALCAL_IPOPT_LOCAL_INSTANCES(extern, M)
SCALCAL_FOR_EACH_SYNTHESIS_MODEL(SCALCAL_EXTERN_IPOPT_LOCAL)
#undef SCALCAL_EXTERN_IPOPT_LOCAL

}  // namespace scalcal
