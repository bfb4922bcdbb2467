// Fedorov's exchange on a finite candidate set: each movable position of a program is replaced by
// the candidate that improves the criterion most, given all the others, until a full pass changes
// nothing. The criterion of each trial comes from K by a rank-two (Woodbury) update, so a trial
// costs O(P^2) and an eigen-decomposition only for a criterion that reads the spectrum. The
// combinatorial stage of designing for a restricted bench (optimize --region, augment), for any
// registered model.
#pragma once
#include <vector>

#include "numeric/criteria/registry.hpp"
#include "numeric/model/model.hpp"
#include "numeric/model/registry.hpp"

namespace scalcal {

struct ExchangeResult {
  std::vector<Vec3> positions;  // the fixed positions first, unchanged, then the movable ones
  double value = 0;             // normalised criterion (infinite while rank-deficient)
  int passes = 0;
  int swaps = 0;
};

// positions: the program; its first `fixed` positions never move. A rank-deficient program is
// ranked by a tiny ridge, so swaps that raise the rank win. max_passes bounds the work.
ExchangeResult exchange(CriterionKind criterion, const std::vector<Vec3>& candidates, std::vector<Vec3> positions,
                        int fixed = 0, int max_passes = 100, ModelKind model = ModelKind::paper9);

// Sequential design: add `count` candidates one at a time, each the best given those before it
// (after the `given` positions), then exchange the added ones.
ExchangeResult greedy_exchange(CriterionKind criterion, const std::vector<Vec3>& candidates,
                               const std::vector<Vec3>& given, int count, ModelKind model = ModelKind::paper9);

// The same for one model type of this build's synthesis (exchanger.hpp; compiled in the model's unit).
template <class Model>
ExchangeResult exchange_for(CriterionKind criterion, const std::vector<Vec3>& candidates, std::vector<Vec3> positions,
                            int fixed, int max_passes);
template <class Model>
ExchangeResult greedy_exchange_for(CriterionKind criterion, const std::vector<Vec3>& candidates,
                                   const std::vector<Vec3>& given, int count);

}  // namespace scalcal
