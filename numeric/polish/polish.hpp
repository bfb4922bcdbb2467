// High-precision confirmation of an optimum: Newton's method on the first-order (KKT) conditions
// in MPFR arithmetic, with least-squares (minimum-norm) steps because symmetries (rotations for D,
// manifolds of 4-designs for N >= 16) make the Jacobian singular. All four criteria: E, whose
// optimum is a multiple eigenvalue, on the nonsmooth conditions of polish_e.cpp.
#pragma once
#include <string>

#include "numeric/criteria/criterion_kind.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

struct PolishOptions {
  int digits = 50;          // significant digits wanted in value_digits
  int max_iterations = 40;
};

struct PolishResult {
  bool supported = false;   // true for every criterion (kept for callers that still check it)
  // Residual small enough that every printed digit is true; for E also that the root passes the
  // checks of a maximum (its lambda is lambda_min, a positive semidefinite dual exists, its E is no
  // worse than the start's); first-order checks, so a saddle can still pass.
  bool converged = false;
  int iterations = 0;       // Jacobians formed (E: summed over the multiplicities tried)
  double residual = 0;      // 2-norm of the first-order conditions at the polished program (NaN: rank < 9)
  int digits = 0;           // significant digits in value_digits (fewer than asked when not converged)
  std::string value_digits; // the normalised criterion, decimal
  Program program;          // the polished program, rounded to double
  int active = 0;           // S: number of active diagonal elements K(r,r) at the optimum
};

// Starts from `program` (a double optimum, e.g. from synthesize). Uses the process-wide MPFR
// default precision while it runs (restored afterwards): call it from one thread at a time.
PolishResult polish(const Program& program, CriterionKind criterion, const PolishOptions& options = {});

}  // namespace scalcal
