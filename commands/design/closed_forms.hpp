// The closed forms the reports quote beside their numbers: the paper's limits on the sphere with the
// moments of an optimal symmetric measure, a cap's proven limit, a thermal limit's temperature factor.
// With GiNaC they are derived (closed_forms_with_ginac.cpp, symbolic/); a build without it
// (-DSCALCAL_WITH_GINAC=OFF, closed_forms_without_ginac.cpp) gives the numbers from numeric/ and the
// stated forms numeric/ holds (which the proof checks derive again), and never a form it did not derive:
// there the text is empty and the reports say only the value, with the theorem that proves it.
#pragma once
#include <optional>
#include <string>

#include "numeric/criteria/registry.hpp"
#include "numeric/region/cap_limits.hpp"

namespace scalcal::commands {

// The paper's model's limit of a criterion on the sphere and the optimal symmetric measure's moments.
struct SphereClosedForm {
  std::string exact;     // the limit, canonical text ("61509375/4")
  double value = 0;      // the limit
  std::string x4, x2y2;  // E[x^4], E[x^2 y^2] as exact text; "" where not derived (without GiNaC)
  double b = 0;          // E[x^2 y^2] as a number
};

// nullopt for a criterion without a known limit on the sphere.
std::optional<SphereClosedForm> sphere_closed_form(CriterionKind c);

// A cap's proven limit as text (symbolic/cap_limits.hpp); "" without GiNaC.
std::string cap_limit_text(CriterionKind c, const CapClosedForm& form);

// The temperature factor of degree k in closed form ("3125/16"), where the interval's optimal design is
// proven (numeric/thermal/interval_design.hpp's closed_form); "" elsewhere and without GiNaC.
std::string interval_factor_text(CriterionKind c, int degree);

}  // namespace scalcal::commands
