// The result of one local optimisation (a start of the multistart) and the options of the local
// solvers; shared by the Newton and Ipopt paths and carried across the worker pipe.
#pragma once
#include "numeric/program/program.hpp"
#include "numeric/program/summary.hpp"

namespace scalcal {

enum class LocalSolver {
  Automatic,  // for smooth criteria Riemannian Newton below N = 40, L-BFGS from there; else Ipopt
  Newton,     // Riemannian Newton for the smooth criteria (and E's trace warm start)
  Lbfgs,      // Riemannian L-BFGS likewise
  Ipopt,      // Ipopt for every start (slower; for comparison)
};

struct LocalOptions {
  double tolerance = 1e-10;  // Ipopt's tol
  // 0: 200 for smooth criteria, 300 for the others. With exact Hessians, starts at N = 24 took
  // 12-18 Ipopt iterations for A, 26-67 for S, 15-197 for E from a random program (D at N = 18:
  // 12-19); one that has not converged by the cap is abandoned: more starts find the optimum
  // sooner than longer ones.
  int max_iterations = 0;
  // > 0: Ipopt also stops, as converged, once three iterations in a row are feasible (constraint
  // violation <= 1e-10), have dual infeasibility <= 1e-6 (Ipopt's default acceptable_tol) and change
  // the objective by at most this much relative to max(1, |f|). On a restricted bench the
  // zone rows leave Ipopt's dual infeasibility stalled near 1e-6 while the objective is already
  // settled: at cap:20 it reached its value to 1e-9 within 12-15 iterations, then wandered in the 9th
  // digit up to the 200-iteration cap (3 of 4 starts at N = 13).
  double settle_tolerance = 0;
};

struct LocalResult {
  Program program;   // unit vectors
  double value = 0;  // normalised criterion of `program`, from evaluate()
  Summary summary;
};

}  // namespace scalcal
