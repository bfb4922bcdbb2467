// Riemannian Newton (sphere_newton.hpp) and L-BFGS (sphere_lbfgs.hpp) as local solvers of the
// multistart, for smooth criteria: a D start at N = 18 takes 0.26 ms by Newton against Ipopt's 7.2 ms
// (bench/), because it needs no KKT factorisation of a 4N-dimensional system; from N = 40 on an
// L-BFGS start is cheaper still (a step costs O(N), not O(N^3)).
#pragma once
#include <cmath>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/synthesis/criterion_ops.hpp"
#include "numeric/synthesis/local_result.hpp"
#include "numeric/synthesis/sphere_lbfgs.hpp"
#include "numeric/synthesis/sphere_newton.hpp"

namespace scalcal {

// Where the smooth criteria switch from Newton to L-BFGS by default. L-BFGS is the faster from N = 20
// on (A, 8 starts and Ipopt's confirmation, one core: 6.5 against 10 ms at N = 20, 58 against 259 ms
// at N = 200), but below N = 40 Newton stays: the sweep's optima at the hard N (9..15, where starts
// end at different local optima) were found with it, and its convergence there is quadratic.
inline constexpr int kLbfgsFromPositions = 40;

// The local solver a smooth criterion's starts use at `positions` when `requested` is Automatic.
inline LocalSolver smooth_local_solver(LocalSolver requested, int positions) {
  if (requested != LocalSolver::Automatic) return requested;
  return positions >= kLbfgsFromPositions ? LocalSolver::Lbfgs : LocalSolver::Newton;
}

// One start by Riemannian Newton or L-BFGS (`solver`), kept only if it lowered the value.
template <class Model>
LocalResult sphere_local(const CriterionOps<Model>& criterion, const Program& start, LocalSolver solver) {
  LocalResult out;
  out.program = start;
  out.value = criterion_value(criterion, start);
  if (!std::isfinite(out.value)) {
    out.summary.message = "rank-deficient start: no local model";
    return out;
  }
  Program moved = start;
  const bool lbfgs = solver == LocalSolver::Lbfgs;
  Summary summary;
  int iterations = 0;
  if (lbfgs) {
    const auto r = SphereLbfgsSolver<Model>(criterion.smooth).run(moved.positions);
    summary = r.summary;
    iterations = r.iterations;
  } else {
    const auto r = SphereNewtonSolver<Model>(criterion.smooth).run(moved.positions);
    summary = r.summary;
    iterations = r.iterations;
  }
  // A failed start (rank-deficient) stays a start that did not converge: its value decides below.
  out.summary.termination = summary.converged() ? Termination::converged : Termination::not_converged;
  out.summary.message = summary.message.empty() ? "stopped before its gradient tolerance" : summary.message;
  out.summary.iterations = iterations;
  const double value = criterion_value(criterion, moved);
  if (std::isfinite(value) && value <= out.value) {
    out.program = std::move(moved);
    out.value = value;
  }
  return out;
}

template <SmoothCriterion C, class Model = Paper9Model>
LocalResult optimize_with_newton(const Program& start) {
  return sphere_local<Model>(criterion_ops<C, Model>(), start, LocalSolver::Newton);
}

template <SmoothCriterion C, class Model = Paper9Model>
LocalResult optimize_with_lbfgs(const Program& start) {
  return sphere_local<Model>(criterion_ops<C, Model>(), start, LocalSolver::Lbfgs);
}

#define SCALCAL_SPHERE_LOCAL_INSTANCES(prefix, M) \
  prefix template LocalResult sphere_local<M>(const CriterionOps<M>&, const Program&, LocalSolver);
#define SCALCAL_EXTERN_SPHERE_LOCAL(M) SCALCAL_SPHERE_LOCAL_INSTANCES(extern, M)
SCALCAL_FOR_EACH_SYNTHESIS_MODEL(SCALCAL_EXTERN_SPHERE_LOCAL)
#undef SCALCAL_EXTERN_SPHERE_LOCAL

}  // namespace scalcal
