// `scalcal limits` (limits.hpp): the paper's model on the sphere from the symbolic minimisation over
// symmetric measures, another model from its own stated limits (each proven in the document it
// names), a region from its optimal measure and certified dual bound.
#include "commands/design/limits.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands/core/region_request.hpp"
#include "commands/core/usage_error.hpp"
#include "commands/design/closed_forms.hpp"
#include "commands/design/gyro_regions.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/region/cap_limits.hpp"
#include "numeric/region/region_limits.hpp"
#include "numeric/synthesis/seeds.hpp"

namespace scalcal::commands {
namespace {

std::optional<SphereLimit> paper9_limit(CriterionKind c) {
  const auto l = sphere_closed_form(c);
  if (!l) return std::nullopt;
  SphereLimit s;
  s.exact = l->exact;
  s.value = l->value;
  s.x4 = l->x4;
  s.x2y2 = l->x2y2;
  s.b = l->b;
  s.theorem = std::string(criterion_limit(c).theorem);
  return s;
}

std::optional<SphereLimit> model_limit(ModelKind model, CriterionKind c) {
  const auto l = stated_limit(model, criterion_name(c));
  if (!l) return std::nullopt;
  SphereLimit s;
  s.exact = std::string(l->exact);
  s.value = l->value;
  s.x4 = std::string(l->x4);
  s.x2y2 = std::string(l->x2y2);
  s.x6 = std::string(l->x6);
  if (!std::isnan(l->b)) s.b = l->b;
  s.measure = std::string(l->measure);
  s.attained = std::string(l->attained);
  s.proof = std::string(visit_model(model, [](auto M) { return decltype(M)::proof; }));
  s.theorem = s.proof;
  return s;
}

}  // namespace

const CommandTable& limits_table() {
  static const CommandTable table{
      "limits",
      "N -> infinity limits of the normalised " + criterion_names_text() +
          " criteria: exact on the sphere, certified bounds on a region",
      61,
      {model_or_thermal_option(), temperature_option(), region_option(), design_instrument_option(),
       out_option("write the limits as CSV, one row per criterion: criterion,limit,exact,lower_bound"),
       json_option("print one JSON object keyed by criterion")}};
  return table;
}

LimitsRequest limits_request(const Values& v) {
  LimitsRequest q;
  q.regions = instrument_regions(v, v.list("--region"));
  q.thermal = parse_thermal_model(v.text("--model"));
  q.model = q.thermal ? q.thermal->base : model_of(v);
  if (v.given("--temperature")) q.temperature = parse_temperature_range(v.text("--temperature"));
  return q;
}

LimitsResult limits(const LimitsRequest& q, const Progress& progress) {
  const bool sphere = is_sphere(q.regions);
  if (q.thermal || q.temperature) {
    if (!q.thermal)
      throw UsageError(words("limits: {temperature} needs a thermal model, {model BASE+Tk} (e.g. paper9+T3)"));
    if (!q.temperature)
      throw UsageError(words("limits: {model} ") + q.thermal->name() +
                       words(" needs {temperature T1..T2} (degrees Celsius)"));
    LimitsResult r;
    r.model = q.model;
    if (!sphere && !model_supports(q.model, ModelCapability::region_limits))
      throw region_limits_refusal("limits", q.thermal->name());
    if (!sphere) r.region = resolve_region(q.regions, r.warnings);
    r.thermal = thermal_limits(*q.thermal, *q.temperature, r.region, progress);
    return r;
  }
  if (!model_supports(q.model, ModelCapability::region_limits) && !sphere)
    throw UsageError(words("limits: {region} has limits for the ") + models_supporting(ModelCapability::region_limits) +
                     words(" model only (got {model} ") + std::string(model_name(q.model)) + ")");
  LimitsResult r;
  r.model = q.model;
  if (!sphere) r.region = resolve_region(q.regions, r.warnings);
  std::vector<RegionLimitTask> tasks;
  std::vector<std::size_t> task_row;
  for (auto c : kCriteria) {
    CriterionLimits l;
    l.criterion = c;
    l.sphere = model_supports(q.model, ModelCapability::criteria_native) ? paper9_limit(c) : model_limit(q.model, c);
    if (r.region && l.sphere) {  // a region's limit is judged against the sphere's, so both must exist
      tasks.push_back({c, *r.region});
      task_row.push_back(r.criteria.size());
      l.sphere_value = l.sphere->value;
    }
    r.criteria.push_back(std::move(l));
  }
  if (tasks.empty()) return r;
  // The criteria's limits side by side, one worker process per core (region_limits.hpp).
  const std::string stage = "limits on " + r.region->text();
  if (progress) progress(stage, 0, static_cast<int>(tasks.size()));
  const std::vector<RegionLimit> limits = region_limits(tasks, {}, thread_count(0), [&](int done, int total) {
    if (progress) progress(stage, done, total);
  });
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    CriterionLimits& row = r.criteria[task_row[i]];
    row.region = limits[i];
    if (!row.region->theorem.empty())
      if (const auto form = cap_closed_form(row.criterion, *r.region))
        row.region_exact = cap_limit_text(row.criterion, *form);
  }
  return r;
}

}  // namespace scalcal::commands
