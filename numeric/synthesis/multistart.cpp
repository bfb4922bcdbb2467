// The runtime multistart: the registered criterion and model chosen at run time, each model's
// solvers compiled in its own unit (synthesis_unit.cpp.in); a registered model left out of this build
// (SCALCAL_MODELS) answers with the models it has.
#include "numeric/synthesis/multistart.hpp"

#include "numeric/model/registry.hpp"
#include "numeric/synthesis/synthesize.hpp"

namespace scalcal {

SynthesisResult synthesize(const SynthesisOptions& options) {
  return visit_model(options.model, [&](auto M) -> SynthesisResult {
    using Model = decltype(M);
    if constexpr (kSynthesisBuilt<Model>) {
      return visit_criterion(options.criterion, [&](auto C) {
        return synthesize_with<Model>(criterion_ops<decltype(C), Model>(), options);
      });
    } else {
      throw_no_synthesis(Model::name);
    }
  });
}

}  // namespace scalcal
