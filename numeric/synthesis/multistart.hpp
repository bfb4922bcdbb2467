// Synthesis of optimal programs: a multistart of a local optimiser over N unit vectors for one
// criterion (Riemannian Newton for smooth criteria, confirmed by Ipopt; Ipopt for the others),
// keeping the best program. Programs equal up to the criterion's symmetry count as one.
// This is the runtime entry (the criterion as a CriterionKind); synthesize.hpp is the template.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "numeric/criteria/registry.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/program.hpp"
#include "numeric/program/summary.hpp"
#include "numeric/synthesis/local_result.hpp"

namespace scalcal {

struct SynthesisOptions {
  int positions = 18;
  CriterionKind criterion = CriterionKind::D;
  ModelKind model = ModelKind::paper9;
  // 0: adaptive, up to the criterion's default count (enough for the global optimum for N <= 30),
  // ending when the stopping rule holds (stopping_rule.hpp); > 0: exactly this many.
  int starts = 0;
  std::uint64_t seed = 1;
  int threads = 0;  // 0: all cores
  LocalSolver local = LocalSolver::Automatic;
  std::function<void(int done, int total)> progress;  // called from one thread at a time
  // Start 0 is this program instead of a random one (optimize --from: a lab's program or a family
  // member as a start); its size must be `positions`.
  std::optional<Program> first_start;
  // Results of starts 0, 1, ... computed elsewhere (by multistart_starts, on another MPI rank): taken as
  // they are instead of running those starts again. Each is what this run would compute, bit for bit,
  // so the result does not depend on where they ran.
  std::vector<LocalResult> known_starts;
};

struct SynthesisResult {
  Program program;
  double value = 0;          // normalised criterion of `program`
  int starts = 0;            // starts run
  std::string stopping;      // what ended the multistart: "8 consecutive hits", "cap 204" or "forced 50"
  int hits = 0;              // starts that reached `value` (to a relative kHitTolerance)
  int distinct = 0;          // distinct programs among the hits, up to the criterion's symmetry
  std::string local_solver;  // "newton" or "ipopt": what ran the starts
  // converged: Ipopt confirmed the best program as a KKT point with the same value (ipopt: the best
  // start converged); the message says which.
  Summary summary;
  double seconds = 0;
};

// Throws std::invalid_argument when positions < the model's P or starts < 0.
SynthesisResult synthesize(const SynthesisOptions& options);

// How many starts every multistart of these options runs, whatever their results (its first batch: the
// criterion's minimum at a deceptive N, or --starts' count), and starts first .. first + count - 1 of it:
// work that can be split among processes ahead of synthesize (SynthesisOptions::known_starts).
int certain_starts(const SynthesisOptions& options);
std::vector<LocalResult> multistart_starts(const SynthesisOptions& options, int first, int count);

}  // namespace scalcal
