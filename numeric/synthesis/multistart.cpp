// The runtime multistart: every registered criterion's template instantiated once, here, for every
// registered model.
#include "numeric/synthesis/multistart.hpp"

#include "numeric/model/registry.hpp"
#include "numeric/synthesis/synthesize.hpp"

namespace scalcal {

SynthesisResult synthesize(const SynthesisOptions& options) {
  return visit_model(options.model, [&](auto M) {
    return visit_criterion(options.criterion, [&](auto C) { return synthesize<decltype(C), decltype(M)>(options); });
  });
}

}  // namespace scalcal
