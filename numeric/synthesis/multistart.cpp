// The runtime multistart: the criterion's form picks the translation unit that instantiates it.
#include "numeric/synthesis/multistart.hpp"

#include "numeric/synthesis/synthesize_by_form.hpp"

namespace scalcal {

SynthesisResult synthesize(const SynthesisOptions& options) {
  return visit_criterion(options.criterion, [&](auto C) {
    return synthesis_detail::synthesize_of_form(typename decltype(C)::Form{}, options);
  });
}

}  // namespace scalcal
