// One local optimisation of a program for one criterion by Ipopt (the building block of the
// multistart in synthesis.cpp). Positions are unit vectors held by norm constraints, so there are
// no angle poles; S and E use exact smooth reformulations (epigraph; M/N - sI = L L^T).
#pragma once
#include "numeric/criteria/criterion_kind.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

struct LocalOptions {
  double tolerance = 1e-10;  // Ipopt's tol
  // 0: the criterion's cap (D, A 200; E, S 300). With exact Hessians, starts at N = 24 took
  // 12-18 Ipopt iterations for A, 26-67 for S, 15-197 for E from a random program (D at N = 18:
  // 12-19); one that has not converged by the cap is abandoned: more starts find the optimum
  // sooner than longer ones.
  int max_iterations = 0;
};

struct LocalResult {
  Program program;     // unit vectors (renormalised after Ipopt)
  double value = 0;    // normalised criterion of `program`, from evaluate()
  bool converged = false;
  int status = 0;      // Ipopt's ApplicationReturnStatus
  int iterations = 0;
};

LocalResult optimize_locally(const Program& start, CriterionKind criterion, const LocalOptions& options = {});

// The other local solver: Riemannian Newton on the spheres (sphere_newton.hpp), for the smooth
// criteria D and A only; a D start at N = 18 takes 0.26 ms against Ipopt's 7.2 ms (bench/), because
// it needs no KKT factorisation of a 4N-dimensional system. status 0: converged.
bool newton_applies(CriterionKind criterion);
LocalResult optimize_by_newton(const Program& start, CriterionKind criterion);

// The normalised criterion of a program (evaluate(), one field); +infinity when rank < 9.
double criterion_value(const Program& program, CriterionKind criterion);

}  // namespace scalcal
