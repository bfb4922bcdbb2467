// When the multistart may stop before its cap: starts run in fixed batches (never sized by the
// number of workers, so the count run depends only on the seed), and after each batch the run ends
// once the last `consecutive_hits` starts in index order all reached the best value found so far.
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "numeric/synthesis/local_result.hpp"
#include "numeric/synthesis/seeds.hpp"

namespace scalcal {

// Why a rule of consecutive hits rather than a count of hits: where the global optimum has a small
// basin (E at N = 9: 17 of 256 starts) a common local optimum would soon collect any fixed number of
// hits, while a run of consecutive hits of the best is broken by every start that lands elsewhere, so
// the multistart goes on to its cap there and stops after one batch where every start finds the
// optimum (D, A and E from N = 14 on: 204/204 starts for D at N = 200).
struct StoppingRule {
  int consecutive_hits = 8;
  int batch = 8;

  // The length of the trailing run of starts whose value is within kHitTolerance of the best.
  static int trailing_hits(const std::vector<LocalResult>& results) {
    double best = results.empty() ? 0 : results.front().value;
    for (const auto& r : results) best = std::min(best, r.value);
    int run = 0;
    for (auto it = results.rbegin(); it != results.rend() && it->value <= best * (1 + kHitTolerance); ++it) ++run;
    return run;
  }

  bool satisfied(const std::vector<LocalResult>& results) const {
    const bool any_finite =
        std::any_of(results.begin(), results.end(), [](const LocalResult& r) { return std::isfinite(r.value); });
    return any_finite && trailing_hits(results) >= consecutive_hits;
  }

  std::string description() const { return std::to_string(consecutive_hits) + " consecutive hits"; }
};

}  // namespace scalcal
