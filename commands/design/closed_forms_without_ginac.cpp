// A build without GiNaC (closed_forms.hpp): the sphere's limits as numeric/criteria states them (the value
// and E[x^2 y^2] evaluated in 50 digits and rounded once, as GiNaC's are; the stated text, which
// proofs/checks derive again), no form of a cap's limit or of a temperature factor.
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "commands/design/closed_forms.hpp"

namespace scalcal::commands {

std::optional<SphereClosedForm> sphere_closed_form(CriterionKind c) {
  using Wide = boost::multiprecision::cpp_bin_float_50;
  if (!has_limit(c)) return std::nullopt;
  const auto l = criterion_limit<Wide>(c);
  return SphereClosedForm{std::string(l.exact), static_cast<double>(l.value), "", "", static_cast<double>(l.moment_b)};
}

std::string cap_limit_text(CriterionKind, const CapClosedForm&) { return ""; }

std::string interval_factor_text(CriterionKind, int) { return ""; }

}  // namespace scalcal::commands
