// Riemannian Newton (sphere_newton.hpp) and L-BFGS (sphere_lbfgs.hpp) as local solvers of the
// multistart, for smooth criteria: a D start at N = 18 takes 0.26 ms by Newton against Ipopt's 7.2 ms
// (bench/), because it needs no KKT factorisation of a 4N-dimensional system; from N = 40 on an
// L-BFGS start is cheaper still (a step costs O(N), not O(N^3)).
#pragma once
#include <cmath>

#include "numeric/criteria/evaluation.hpp"
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

// One start by `Solver` (SphereNewton or SphereLbfgs), kept only if it lowered the value.
template <SmoothCriterion C, class Model, class Solver>
LocalResult optimize_on_sphere(const Program& start, const char* converged_message) {
  LocalResult out;
  out.program = start;
  out.value = criterion_value<C, Model>(start);
  if (!std::isfinite(out.value)) {
    out.summary.message = "rank-deficient start: no local model";
    return out;
  }
  Program moved = start;
  const auto r = Solver().run(moved.positions);
  out.summary.iterations = r.iterations;
  out.summary.termination = r.converged ? Termination::converged : Termination::not_converged;
  out.summary.message = r.converged ? converged_message : "stopped before its gradient tolerance";
  const double value = criterion_value<C, Model>(moved);
  if (std::isfinite(value) && value <= out.value) {
    out.program = std::move(moved);
    out.value = value;
  }
  return out;
}

template <SmoothCriterion C, class Model = Paper9Model>
LocalResult optimize_with_newton(const Program& start) {
  return optimize_on_sphere<C, Model, SphereNewton<C, Model>>(start, "Riemannian gradient below tolerance (Newton)");
}

template <SmoothCriterion C, class Model = Paper9Model>
LocalResult optimize_with_lbfgs(const Program& start) {
  return optimize_on_sphere<C, Model, SphereLbfgs<C, Model>>(start, "Riemannian gradient below tolerance (L-BFGS)");
}

}  // namespace scalcal
