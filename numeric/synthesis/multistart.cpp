// The runtime multistart: every registered criterion's template instantiated once, here, for the
// paper's model.
#include "numeric/synthesis/multistart.hpp"

#include "numeric/synthesis/synthesize.hpp"

namespace scalcal {

SynthesisResult synthesize(const SynthesisOptions& options) {
  return visit_criterion(options.criterion, [&](auto C) { return synthesize<decltype(C), Paper9Model>(options); });
}

}  // namespace scalcal
