// The runtime polish: every registered criterion under the paper's model. The MPFR work is in
// polish_kkt.cpp, polish_eigenvalue.cpp and polish_value.cpp (one instantiation each, compiled side by
// side), reached through the criterion's PolishOps.
#include "numeric/polish/polish.hpp"

#include "numeric/polish/polish_form.hpp"

namespace scalcal {

PolishResult polish(const Program& program, CriterionKind criterion, const PolishOptions& options) {
  return visit_criterion(criterion, [&](auto C) { return polish<decltype(C), Paper9Model>(program, options); });
}

}  // namespace scalcal
