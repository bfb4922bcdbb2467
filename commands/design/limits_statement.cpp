// The limit a report judges a program against (limits_statement.hpp).
#include "commands/design/limits_statement.hpp"

#include <stdexcept>

#include "commands/design/closed_forms.hpp"
#include "numeric/region/cap_limits.hpp"

namespace scalcal::commands {

std::optional<ReportedLimit> reported_limit(CriterionKind c, ModelKind model, const std::optional<Region>& region) {
  ReportedLimit out;
  if (!model_supports(model, ModelCapability::criteria_native)) {  // a model's stated limits: on the sphere only
    const auto l = stated_limit(model, criterion_name(c));
    if (!l) return std::nullopt;
    const std::string_view proof = visit_model(model, [](auto M) { return decltype(M)::proof; });
    out.statement = {l->value, l->value, LimitStatus::proven, proof};
    out.exact = std::string(l->exact);
    return out;
  }
  try {
    out.statement = limit_statement(c, region ? *region : sphere_region());
  } catch (const std::invalid_argument&) {  // no known limit for this criterion
    return std::nullopt;
  }
  if (out.statement.status != LimitStatus::proven) return out;
  if (!region || region->is_sphere())
    out.exact = std::string(criterion_limit(c).exact);
  else if (const auto form = cap_closed_form(c, *region))
    out.exact = cap_limit_text(c, *form);
  return out;
}

Json to_json(const ReportedLimit& l) {
  Json j{{"value", l.statement.value}, {"status", std::string(status_name(l.statement.status))}};
  j["lower_bound"] = l.statement.lower_bound ? Json(*l.statement.lower_bound) : Json(nullptr);
  if (l.statement.status == LimitStatus::proven) {
    j["exact"] = l.exact.empty() ? Json(nullptr) : Json(l.exact);  // none derived (a build without GiNaC)
    j["theorem"] = std::string(l.statement.theorem);
  }
  return j;
}

}  // namespace scalcal::commands
