// The runtime multistart: the registered criterion and model chosen at run time, each model's
// solvers compiled in its own unit (synthesis_unit.cpp.in); a registered model left out of this build
// (SCALCAL_MODELS) answers with the models it has.
#include "numeric/synthesis/multistart.hpp"

#include "numeric/model/registry.hpp"
#include "numeric/synthesis/synthesize.hpp"

namespace scalcal {

namespace {

// f(criterion_ops) for the options' model and criterion, or the error of a model this build left out.
template <class Result, class F>
Result with_ops(const SynthesisOptions& options, F&& f) {
  return visit_model(options.model, [&](auto M) -> Result {
    using Model = decltype(M);
    if constexpr (kSynthesisBuilt<Model>) {
      return visit_criterion(options.criterion,
                             [&](auto C) -> Result { return f(criterion_ops<decltype(C), Model>()); });
    } else {
      throw_no_synthesis(Model::name);
    }
  });
}

}  // namespace

SynthesisResult synthesize(const SynthesisOptions& options) {
  return with_ops<SynthesisResult>(options, [&](const auto& ops) { return synthesize_with(ops, options); });
}

int certain_starts(const SynthesisOptions& options) {
  return with_ops<int>(options, [&](const auto& ops) { return certain_starts_with(ops, options); });
}

std::vector<LocalResult> multistart_starts(const SynthesisOptions& options, int first, int count) {
  return with_ops<std::vector<LocalResult>>(
      options, [&](const auto& ops) { return multistart_starts_with(ops, options, first, count); });
}

}  // namespace scalcal
