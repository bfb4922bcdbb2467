// The exact text of a cap's proven limit (numeric/region/cap_limits.hpp says where a theorem gives one):
// the half-angle as the decimal it was written as, c = cos of it as GiNaC knows it (0 on the hemisphere,
// sqrt(3)/2 at 30 degrees, cos(1/18*Pi) at 10), E and S as their closed forms at that c, D as
// proofs/cap_d_limit.md writes it with the quintic at that c.
#pragma once
#include <string>

#include <ginac/ginac.h>

#include "numeric/region/cap_limits.hpp"

namespace scalcal::symbolic {

// cos(half-angle) exactly: the half-angle's shortest decimal text read as a rational number of degrees.
GiNaC::ex cap_cosine(double half_angle_deg);

// The closed form at the cap's c: "147", "5283", radicals at 30 or 45 degrees (canonical), or where c stays
// cos(...) the theorem's "(3*c^4+...)/(1-c)^4 at c = cos(1/18*Pi)"; D's "61509375/4" beyond 133.62 degrees, and
// below "D(alpha(c), t(c); c) at c = 0, t(c) the root in (0, 1) of 18-29*t^2-26*t^3-29*t^4+10*t^5".
std::string cap_limit_exact(CriterionKind c, const CapClosedForm& form);

// The same as an expression where it is one (E, S, D at the sphere's limit); D below 133.62 degrees
// is an algebraic number given by its quintic: its value is form.value, checked by the tests.
GiNaC::ex cap_limit_expression(CriterionKind c, const CapClosedForm& form);

}  // namespace scalcal::symbolic
