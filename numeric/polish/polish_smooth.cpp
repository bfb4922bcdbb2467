// The polish of every registered criterion of the SmoothForm, for the paper's model.
#include "numeric/polish/polish_by_form.hpp"
#include "numeric/polish/polish_form.hpp"

namespace scalcal::polish_detail {

PolishResult polish_of_form(SmoothForm, const Program& program, CriterionKind criterion, const PolishOptions& options) {
  return visit_criterion_of_form<PolishResult, SmoothForm>(
      criterion, [&](auto C) { return polish<decltype(C), Paper9Model>(program, options); });
}

}  // namespace scalcal::polish_detail
