// The runtime polish: every registered criterion's template instantiated once, here, for the
// paper's model (the MPFR templates are the costliest code to compile in scalcal: one file, because
// split by criterion form the three files re-instantiated the same MPFR SVD, QR and products, 261 s
// against 111 s).
#include "numeric/polish/polish.hpp"

#include "numeric/polish/polish_form.hpp"

namespace scalcal {

PolishResult polish(const Program& program, CriterionKind criterion, const PolishOptions& options) {
  return visit_criterion(criterion, [&](auto C) { return polish<decltype(C), Paper9Model>(program, options); });
}

}  // namespace scalcal
