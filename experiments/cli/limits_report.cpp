#include "experiments/cli/limits_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include "experiments/cli/command.hpp"
#include "experiments/cli/region_option.hpp"
#include "numeric/region/region_limit.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"

namespace scalcal::cli {
namespace {

double number(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(); }

Report sphere_limits() {
  using symbolic::canonical_text;
  Json out = Json::object();
  std::ostringstream text;
  for (auto c : kCriteria) {
    const auto l = symbolic::symbolic_limit(c);
    {  // the text line; the decimal only where it says something the exact form does not ("E >= 12")
      const std::string exact = canonical_text(l.value);
      std::ostringstream decimal;
      decimal << number(l.value);
      text << criterion_name(c) << " >= " << exact << (decimal.str() == exact ? "" : " = " + decimal.str())
           << "   optimal moments: E[x^2] = 1/3, E[x^4] = " << canonical_text(l.x4)
           << ", E[x^2 y^2] = " << canonical_text(l.b) << ", odd moments and other mixed moments 0\n";
    }
    out[std::string(criterion_name(c))] = Json{
        {"exact", canonical_text(l.value)},
        {"value", number(l.value)},
        {"moments",
         Json{{"E[x^2]", "1/3"}, {"E[x^4]", canonical_text(l.x4)}, {"E[x^2 y^2]", canonical_text(l.b)}, {"odd", "0"}}},
        {"b", number(l.b)}};
  }
  return Report{out, text.str()};
}

// A model other than the paper's states its limits in its own file (numeric/model/), each proven
// in the proof document it names (checked under ctest -L proof).
Report model_limits(ModelKind model) {
  Json out = Json::object();
  std::ostringstream text;
  for (auto c : kCriteria) {
    const auto l = stated_limit(model, criterion_name(c));
    if (!l) continue;
    Json moments = Json{{"E[x^2]", "1/3"}};
    if (!l->x4.empty()) moments["E[x^4]"] = std::string(l->x4);
    if (!l->x2y2.empty()) moments["E[x^2 y^2]"] = std::string(l->x2y2);
    if (!l->x6.empty()) moments["E[x^6]"] = std::string(l->x6);
    moments["odd"] = "0";
    const std::string proof(visit_model(model, [](auto M) { return decltype(M)::proof; }));
    {
      std::ostringstream decimal;
      decimal << l->value;
      const std::string exact(l->exact);
      text << criterion_name(c) << " >= " << exact << (decimal.str() == exact ? "" : " = " + decimal.str())
           << "   optimal measure: " << l->measure << "; attained: " << l->attained << "\n";
    }
    out[std::string(criterion_name(c))] = Json{{"exact", std::string(l->exact)},
                                               {"value", l->value},
                                               {"moments", moments},
                                               {"b", std::isnan(l->b) ? Json(nullptr) : Json(l->b)},
                                               {"measure", std::string(l->measure)},
                                               {"attained", std::string(l->attained)},
                                               {"proof", proof}};
  }
  Json j = Json::object();
  j["model"] = std::string(model_name(model));
  for (auto& [k, v] : out.items()) j[k] = v;
  {
    text << "(model " << model_name(model) << ", " << model_parameters(model)
         << " parameters; proofs: " << visit_model(model, [](auto M) { return decltype(M)::proof; }) << ")\n";
  }
  return Report{j, text.str()};
}

std::string decimal(const char* format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

Report region_limits(const std::vector<std::string>& regions) {
  const Region region = resolve_region(regions, "limits");
  Json out = Json::object();
  std::ostringstream text;
  out["region"] = region.text();
  text << "region " << region.text() << "\n";
  for (auto c : kCriteria) {
    if (progress_enabled()) std::cerr << "limits: " << criterion_name(c) << " on " << region.text() << "\n";
    const RegionLimit l = region_limit(c, region);
    const double sphere = criterion_limit(c).value;
    Json support = Json::array();
    for (std::size_t i = 0; i < l.support.size(); ++i)
      support.push_back(
          Json{{"position", Json{l.support[i].x(), l.support[i].y(), l.support[i].z()}}, {"weight", l.weights[i]}});
    Json entry{{"value", l.value}};
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
    out[std::string(criterion_name(c))] = entry;
    text << criterion_name(c) << " >= " << decimal("%.10g", l.value) << " (numerically, an optimal measure on "
         << l.candidates << " candidates)";
    if (l.lower_bound)
      text << "; proven >= " << decimal("%.10g", *l.lower_bound) << " (gap "
           << decimal("%.2g", (l.value - *l.lower_bound) / l.value) << " relative)";
    text << "; " << decimal("%.4g", l.value / sphere) << " x the sphere's; support " << l.support.size()
         << " positions\n";
  }
  return Report{out, text.str()};
}

}  // namespace

Report limits_report(ModelKind model, const std::vector<std::string>& regions) {
  const bool sphere = regions.empty() || (regions.size() == 1 && regions[0] == "sphere");
  if (model != ModelKind::paper9) {
    if (!sphere)
      throw UsageError("limits: --region has limits for the paper9 model only (got --model " +
                       std::string(model_name(model)) + ")");
    return model_limits(model);
  }
  return sphere ? sphere_limits() : region_limits(regions);
}

}  // namespace scalcal::cli
