// The multistart of every registered criterion of the MaxEigenvalueForm, for the paper's model.
#include "numeric/synthesis/synthesize.hpp"
#include "numeric/synthesis/synthesize_by_form.hpp"

namespace scalcal::synthesis_detail {

SynthesisResult synthesize_of_form(MaxEigenvalueForm, const SynthesisOptions& options) {
  return visit_criterion_of_form<SynthesisResult, MaxEigenvalueForm>(
      options.criterion, [&](auto C) { return synthesize<decltype(C), Paper9Model>(options); });
}

}  // namespace scalcal::synthesis_detail
