// Synthesis of optimal programs (contract; implemented in synthesis.cpp): a multistart of a
// local optimiser (Ipopt) over N unit vectors for one criterion, keeping the best program.
// Programs equal up to a rotation (D) or a signed permutation of the axes count as one.
#pragma once
#include <cstdint>
#include <functional>

#include "numeric/criterion_kind.hpp"
#include "numeric/program.hpp"

namespace scalcal {

struct SynthesisOptions {
  int positions = 18;
  CriterionKind criterion = CriterionKind::D;
  int starts = 0;            // 0: the default, chosen to find the global optimum for N <= 30
  std::uint64_t seed = 1;
  int threads = 0;           // 0: all cores
  std::function<void(int done, int total)> progress;  // called from one thread at a time
};

struct SynthesisResult {
  Program program;
  double value = 0;  // normalised criterion of `program`
  int starts = 0;
  int hits = 0;      // starts that reached `value` (to a relative 1e-8)
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
