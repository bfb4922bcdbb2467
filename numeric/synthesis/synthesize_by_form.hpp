// The runtime multistart, one translation unit per criterion form (synthesize_<form>.cpp), so that
// two cores compile the solvers' templates in parallel. multistart.cpp picks the overload by the
// criterion's Form; a new form needs its own file.
#pragma once
#include "numeric/synthesis/multistart.hpp"

namespace scalcal::synthesis_detail {

SynthesisResult synthesize_of_form(SmoothForm, const SynthesisOptions& options);
SynthesisResult synthesize_of_form(MaxDiagonalForm, const SynthesisOptions& options);
SynthesisResult synthesize_of_form(MaxEigenvalueForm, const SynthesisOptions& options);

}  // namespace scalcal::synthesis_detail
