// The exact temperature factor of a thermal model's limits (Theorem 25, proofs/thermal_product.md):
// the optimal design's criterion for polynomial regression of degree k on [-1, 1], as a rational.
// D for k = 1..6 from the Lobatto design's moments (power sums of the roots of P_k', rational by
// Newton's identities); A, E and S for k = 1, 2 and E and S for k = 3 from their closed-form designs.
#pragma once
#include <string>

#include <ginac/ginac.h>

#include "numeric/criteria/registry.hpp"

namespace scalcal::symbolic {

// The factor as an exact number; an empty ex (is_zero()) where no closed form is proven.
GiNaC::ex interval_factor_exact(CriterionKind c, int degree);

}  // namespace scalcal::symbolic
