// High-precision confirmation of an optimum: Newton's method on the first-order (KKT) conditions
// in MPFR arithmetic, from a double optimum, for every criterion form (polish_form.hpp). The
// polished program comes back with the value to the digits its residual vouches for.
#pragma once
#include <string>

#include "numeric/criteria/registry.hpp"
#include "numeric/program/program.hpp"
#include "numeric/program/summary.hpp"

namespace scalcal {

struct PolishOptions {
  int digits = 50;  // significant digits wanted in value_digits
  int max_iterations = 40;
};

struct PolishResult {
  // converged: the residual is small enough that every printed digit is true; for the eigenvalue
  // form also that the root passes the checks of a maximum (its lambda is lambda_min, a positive
  // semidefinite dual exists, its E is no worse than the start's). First-order checks: a saddle can
  // still pass. summary.iterations counts Jacobians (E: summed over the multiplicities tried).
  Summary summary;
  double residual = 0;       // 2-norm of the first-order conditions at the polished program (NaN: rank < P)
  int digits = 0;            // significant digits in value_digits (fewer than asked when not converged)
  std::string value_digits;  // the normalised criterion, decimal
  Program program;           // the polished program, rounded to double
  int active = 0;            // max-diagonal form: number of active diagonal elements K(r,r)

  bool converged() const { return summary.converged(); }
};

// Starts from `program` (a double optimum, e.g. from synthesize). Uses the process-wide MPFR
// default precision while it runs (restored afterwards): call it from one thread at a time.
// Throws std::invalid_argument for digits < 1 or a program with fewer positions than parameters.
PolishResult polish(const Program& program, CriterionKind criterion, const PolishOptions& options = {});

}  // namespace scalcal
