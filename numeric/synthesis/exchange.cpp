// The runtime entries of the exchange: the model's own unit (exchanger.hpp) does the work.
#include "numeric/synthesis/exchange.hpp"

#include "numeric/synthesis/synthesis_models.hpp"

namespace scalcal {

ExchangeResult exchange(CriterionKind criterion, const std::vector<Vec3>& candidates, std::vector<Vec3> positions,
                        int fixed, int max_passes, ModelKind model) {
  return visit_model(model, [&](auto M) -> ExchangeResult {
    using Model = decltype(M);
    if constexpr (kSynthesisBuilt<Model>)
      return exchange_for<Model>(criterion, candidates, std::move(positions), fixed, max_passes);
    else
      throw_no_synthesis(Model::name);
  });
}

ExchangeResult greedy_exchange(CriterionKind criterion, const std::vector<Vec3>& candidates,
                               const std::vector<Vec3>& given, int count, ModelKind model) {
  return visit_model(model, [&](auto M) -> ExchangeResult {
    using Model = decltype(M);
    if constexpr (kSynthesisBuilt<Model>)
      return greedy_exchange_for<Model>(criterion, candidates, given, count);
    else
      throw_no_synthesis(Model::name);
  });
}

}  // namespace scalcal
