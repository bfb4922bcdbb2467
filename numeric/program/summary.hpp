// How a solver run ended, shared by every result (local starts, the multistart, the polish), in the
// manner of Ceres' Solver::Summary: one termination and a message a person can read.
#pragma once
#include <string>

namespace scalcal {

enum class Termination {
  converged,      // met its own convergence test
  not_converged,  // stopped (iteration cap, stall) with a usable but unproven result
  failed,         // no usable result (rank-deficient start, solver error)
};

struct Summary {
  Termination termination = Termination::failed;
  std::string message;
  int iterations = 0;

  bool converged() const { return termination == Termination::converged; }
};

inline const char* termination_name(Termination t) {
  return t == Termination::converged ? "converged" : t == Termination::not_converged ? "not_converged" : "failed";
}

}  // namespace scalcal
