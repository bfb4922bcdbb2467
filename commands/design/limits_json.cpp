// The JSON form of `scalcal limits` (limits.hpp): keyed by criterion; a criterion without a known
// limit is null. Each limit says what stands behind it: `status` proven (with `exact` and `theorem`),
// certified (`lower_bound` proven, `value` an optimal measure's) or numerical.
#include <algorithm>
#include <cmath>

#include "commands/design/limits.hpp"

namespace scalcal::commands {
namespace {

Json sphere_json(const SphereLimit& s, bool stated) {
  Json moments{{"E[x^2]", "1/3"}};
  if (!s.x4.empty()) moments["E[x^4]"] = s.x4;
  if (!s.x2y2.empty()) moments["E[x^2 y^2]"] = s.x2y2;
  if (!s.x6.empty()) moments["E[x^6]"] = s.x6;
  moments["odd"] = "0";
  Json j{{"exact", s.exact}, {"value", s.value}, {"moments", moments}, {"b", s.b ? Json(*s.b) : Json(nullptr)}};
  j["status"] = "proven";
  j["theorem"] = s.theorem;
  if (stated) {
    j["measure"] = s.measure;
    j["attained"] = s.attained;
    j["proof"] = s.proof;
  }
  return j;
}

Json region_json(const RegionLimit& l, const std::string& exact, double sphere) {
  Json support = Json::array();
  for (std::size_t i = 0; i < l.support.size(); ++i)
    support.push_back(
        Json{{"position", Json{l.support[i].x(), l.support[i].y(), l.support[i].z()}}, {"weight", l.weights[i]}});
  Json entry{{"value", l.value}};
  entry["status"] = std::string(status_name(status_of(l)));
  if (!l.theorem.empty()) {
    entry["exact"] = exact.empty() ? Json(nullptr) : Json(exact);  // null: not derived (a build without GiNaC)
    entry["theorem"] = std::string(l.theorem);
  }
  entry["lower_bound"] = l.lower_bound ? Json(*l.lower_bound) : Json(nullptr);
  entry["relative_to_sphere"] = l.value / sphere;
  entry["support"] = support;
  entry["candidates"] = l.candidates;
  entry["refinements"] = l.refinements;
  entry["equivalence_gap"] = l.equivalence_gap;
  // The optimal measure's RMS errors per group, theta_q = sqrt(max K(r,r)) (normalised as N = 1).
  for (int g = 0; g < 3; ++g) {
    double worst = 0;
    for (int r : group_members<Paper9Model>(static_cast<ParameterGroup>(g))) worst = std::max(worst, l.K(r, r));
    entry["theta_" + std::string(kGroupNames[static_cast<std::size_t>(g)])] = std::sqrt(worst);
  }
  return entry;
}

}  // namespace

Json to_json(const LimitsResult& r) {
  if (r.thermal) return to_json(*r.thermal);
  Json j = Json::object();
  if (!is_default_model(r.model)) j["model"] = std::string(model_name(r.model));
  if (r.region) j["region"] = r.region->text();
  for (const auto& l : r.criteria) {
    const std::string key(criterion_name(l.criterion));
    if (r.region)
      j[key] = l.region ? region_json(*l.region, l.region_exact, *l.sphere_value) : Json(nullptr);
    else if (l.sphere)
      j[key] = sphere_json(*l.sphere, !model_supports(r.model, ModelCapability::criteria_native));
    else if (model_supports(r.model, ModelCapability::criteria_native))
      j[key] = nullptr;  // no known limit (another model's JSON lists only what it states)
  }
  return j;
}

}  // namespace scalcal::commands
