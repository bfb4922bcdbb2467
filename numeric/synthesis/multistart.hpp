// Synthesis of optimal programs (contract; implemented in synthesis.cpp): a multistart of a
// local optimiser (Riemannian Newton for D and A, Ipopt for E and S) over N unit vectors for one
// criterion, keeping the best program, which Ipopt confirms as a KKT point.
// Programs equal up to a rotation (D) or a signed permutation of the axes count as one.
#pragma once
#include <cstdint>
#include <functional>
#include <string>

#include "numeric/criteria/criterion_kind.hpp"
#include "numeric/program/program.hpp"

namespace scalcal {

enum class LocalSolver {
  Automatic,  // Riemannian Newton where the criterion is smooth (D, A), else Ipopt
  Ipopt,      // Ipopt for every start (slower; for comparison)
};

struct SynthesisOptions {
  int positions = 18;
  CriterionKind criterion = CriterionKind::D;
  int starts = 0;            // 0: the default, chosen to find the global optimum for N <= 30
  std::uint64_t seed = 1;
  int threads = 0;           // 0: all cores
  LocalSolver local = LocalSolver::Automatic;
  std::function<void(int done, int total)> progress;  // called from one thread at a time
};

struct SynthesisResult {
  Program program;
  double value = 0;  // normalised criterion of `program`
  int starts = 0;
  int hits = 0;      // starts that reached `value` (to a relative 1e-8)
  int distinct = 0;  // distinct programs among the hits, up to the criterion's symmetry (program_equivalence.hpp)
  std::string local_solver;  // "newton" or "ipopt": what ran the starts
  bool confirmed = false;    // Ipopt converged at `program` with the same value (ipopt: the best start converged)
  double seconds = 0;
};

SynthesisResult synthesize(const SynthesisOptions& options);

struct RandomSearchResult {
  Program program;  // the best of `count` random programs
  double best = 0;
  long long count = 0;
  double seconds = 0;
};

// The best of `count` programs uniform on the sphere (the paper's dashed line), on all cores.
RandomSearchResult random_search(int positions, long long count, CriterionKind criterion, std::uint64_t seed,
                                 int threads = 0);

}  // namespace scalcal
