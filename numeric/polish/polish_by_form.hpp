// The runtime polish, one translation unit per criterion form (polish_<form>.cpp): the MPFR
// templates are scalcal's costliest code to compile, and split this way two cores build them in
// parallel. polish.cpp picks the overload by the criterion's Form; a new form needs its own file.
#pragma once
#include "numeric/polish/polish.hpp"

namespace scalcal::polish_detail {

PolishResult polish_of_form(SmoothForm, const Program& program, CriterionKind criterion, const PolishOptions& options);
PolishResult polish_of_form(MaxDiagonalForm, const Program& program, CriterionKind criterion,
                            const PolishOptions& options);
PolishResult polish_of_form(MaxEigenvalueForm, const Program& program, CriterionKind criterion,
                            const PolishOptions& options);

}  // namespace scalcal::polish_detail
