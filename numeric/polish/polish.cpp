// The runtime polish: the criterion's form picks the translation unit that instantiates it.
#include "numeric/polish/polish.hpp"

#include "numeric/polish/polish_by_form.hpp"

namespace scalcal {

PolishResult polish(const Program& program, CriterionKind criterion, const PolishOptions& options) {
  return visit_criterion(criterion, [&](auto C) {
    return polish_detail::polish_of_form(typename decltype(C)::Form{}, program, criterion, options);
  });
}

}  // namespace scalcal
