// The closed forms derived with GiNaC (closed_forms.hpp): the only unit of commands/design that needs it.
#include "commands/design/closed_forms.hpp"

#include "symbolic/cap_limits.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"
#include "symbolic/thermal_limits.hpp"

namespace scalcal::commands {
namespace {

double number(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(); }

}  // namespace

std::optional<SphereClosedForm> sphere_closed_form(CriterionKind c) {
  if (!symbolic::has_symbolic_limit(c)) return std::nullopt;
  const auto l = symbolic::symbolic_limit(c);
  return SphereClosedForm{symbolic::canonical_text(l.value), number(l.value), symbolic::canonical_text(l.x4),
                          symbolic::canonical_text(l.b), number(l.b)};
}

std::string cap_limit_text(CriterionKind c, const CapClosedForm& form) { return symbolic::cap_limit_exact(c, form); }

std::string interval_factor_text(CriterionKind c, int degree) {
  const GiNaC::ex one = symbolic::interval_factor_exact(c, degree);
  return one.is_zero() ? std::string() : symbolic::canonical_text(one);
}

}  // namespace scalcal::commands
