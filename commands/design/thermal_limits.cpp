// A thermal model's limits (thermal_limits.hpp): the base model's proven sphere limit times the
// interval's optimal value, exact where symbolic/thermal_limits.hpp has the interval's closed form.
#include "commands/design/thermal_limits.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "commands/core/common_options.hpp"
#include "commands/design/closed_forms.hpp"
#include "numeric/region/cap_limits.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/region/region_limits.hpp"
#include "numeric/synthesis/seeds.hpp"

namespace scalcal::commands {
namespace {

// The base model's factor: its limit on the sphere or the region, whether a theorem proves it and its exact
// text there (closed_forms.hpp: "" in a build without GiNaC), a certified lower bound where interval
// arithmetic encloses it.
struct BaseFactor {
  double value = NAN;
  bool proven = false;
  std::string exact;                  // "" where none is proven or derived
  std::optional<double> lower_bound;  // certified (a region's)
};

BaseFactor sphere_factor(ModelKind model, CriterionKind c) {
  if (model_supports(model, ModelCapability::criteria_native)) {
    const auto l = sphere_closed_form(c);
    if (!l) return {};
    return {l->value, true, l->exact, {}};
  }
  const auto l = stated_limit(model, criterion_name(c));
  if (!l) return {};
  return {l->value, true, std::string(l->exact), {}};
}

// paper9's limits on a region, the criteria side by side (one worker process per core, as `limits` runs them).
std::vector<BaseFactor> region_factors(const Region& region, const Progress& progress) {
  std::vector<RegionLimitTask> tasks;
  for (CriterionKind c : kCriteria)
    if (sphere_closed_form(c)) tasks.push_back({c, region});  // a limit on the sphere: one on a region too
  const std::string stage = "limits on " + region.text();
  const std::vector<RegionLimit> limits = region_limits(tasks, {}, thread_count(0), [&](int done, int total) {
    if (progress) progress(stage, done, total);
  });
  std::vector<BaseFactor> out(kCriterionCount);
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    BaseFactor& f = out[static_cast<std::size_t>(tasks[i].criterion.index())];
    f.value = limits[i].value;
    f.lower_bound = limits[i].lower_bound;
    if (status_of(limits[i]) == LimitStatus::proven)
      if (const auto form = cap_closed_form(tasks[i].criterion, region)) {
        f.proven = true;
        f.exact = cap_limit_text(tasks[i].criterion, *form);
      }
  }
  return out;
}

std::string power(const std::string& base, int exponent) {
  const bool plain = std::all_of(base.begin(), base.end(),
                                 [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; });
  const std::string b = plain ? base : "(" + base + ")";
  return exponent == 1 ? b : b + "^" + std::to_string(exponent);
}

std::string exact_form_of(CriterionKind c, const ThermalModel& m, const std::string& s, const std::string& one) {
  const int k = m.degree, P = m.base_parameters();
  const bool full = static_cast<int>(m.drifting().size()) == P;
  if (c == CriterionKind::D)
    return full ? power(s, k + 1) + " * " + power(one, P)
                : power(s, 1) + " * " + power("27", k) + " * " + power(one, 3);
  if (c == CriterionKind::A && !full) return "9 * " + power(one, 1) + " + " + power(s, 1) + " - 9";
  return power(s, 1) + " * " + power(one, 1);
}

std::string exact_form(CriterionKind c, const ThermalModel& m, const std::string& factor, const std::string& one) {
  // A factor given as a description (a cap's D: "D(alpha(c), t(c); c) at c = ...") is named and stated after.
  const bool described = factor.find(' ') != std::string::npos;
  const std::string s = described ? std::string(criterion_name(c)) + "_s" : factor;
  const std::string tail = described ? "; " + s + " = " + factor : "";
  return exact_form_of(c, m, s, one) + tail;
}

}  // namespace

ThermalLimitsResult thermal_limits(const ThermalModel& model, const TemperatureRange& range,
                                   const std::optional<Region>& region, const Progress& progress) {
  ThermalLimitsResult r{model, range, region, {}};
  const bool full = static_cast<int>(model.drifting().size()) == model.base_parameters();
  const std::vector<BaseFactor> factors =
      region && full ? region_factors(*region, progress) : std::vector<BaseFactor>{};
  for (CriterionKind c : kCriteria) {
    ThermalLimitRow row;
    row.criterion = c;
    const BaseFactor f =
        region ? (full ? factors[static_cast<std::size_t>(c.index())] : BaseFactor{}) : sphere_factor(model.base, c);
    row.limit = thermal_limit(c, model, f.value);
    if (!row.limit) {
      row.note = region && !full ? "Theorem 25's bias-only part rests on the sphere's symmetry; on a region only a "
                                   "model whose every parameter drifts has its limits stated"
                 : !std::isfinite(f.value) ? "the base model has no known limit for this criterion"
                 : !full
                     ? "Theorem 25 gives D and A only when only the biases drift; optimize finds programs numerically"
                     : "no thermal form of this criterion (numeric/thermal/information_criteria.hpp)";
      r.rows.push_back(row);
      continue;
    }
    // The temperature factor is proven where its optimal design is (numeric/thermal/interval_design.hpp).
    const bool proven_one = row.limit->temperature.closed_form;
    const std::string one = interval_factor_text(c, model.degree);
    if (proven_one && f.proven) {
      row.status = "proven";
      if (!one.empty() && !f.exact.empty()) row.exact = exact_form(c, model, f.exact, one);
    } else if (proven_one && f.lower_bound) {
      row.status = "certified";
      row.limit->lower_bound = thermal_limit(c, model, *f.lower_bound)->value;
      row.note = "the region's factor enclosed by interval arithmetic, the temperature's exact";
    } else {
      row.status = "numerical";
      char text[200];
      if (!region || f.lower_bound) {
        if (region) row.limit->lower_bound = thermal_limit(c, model, *f.lower_bound)->lower_bound;
        std::snprintf(text, sizeof text,
                      "the interval's factor found numerically; no design does better than %.10g (convexity bound "
                      "on a grid of 20001 temperatures%s)",
                      row.limit->lower_bound, region ? ", the region's certified bound" : "");
      } else {
        row.limit->lower_bound = NAN;
        std::snprintf(text, sizeof text, "the region's factor found numerically, with no certified bound");
      }
      row.note = text;
    }
    r.rows.push_back(row);
  }
  return r;
}

Json to_json(const ThermalLimitsResult& r) {
  Json j{{"model", r.model.name()},
         {"region", r.region ? Json(r.region->text()) : Json(nullptr)},
         {"parameters", r.model.parameters()},
         {"temperature_c", r.range.text()},
         {"tau", "(T - " + shortest_text(r.range.middle()) + ") / " + shortest_text(r.range.half_range())}};
  for (const auto& row : r.rows) {
    const std::string key(criterion_name(row.criterion));
    if (!row.limit) {
      j[key] = Json{{"value", nullptr}, {"note", row.note}};
      continue;
    }
    const ThermalLimit& l = *row.limit;
    Json setpoints = Json::array();
    for (std::size_t i = 0; i < l.temperature.points.size(); ++i)
      setpoints.push_back(Json{{"t_c", r.range.celsius(l.temperature.points[i])},
                               {"tau", l.temperature.points[i]},
                               {"weight", l.temperature.weights[i]}});
    Json e{{"value", l.value},
           {"status", row.status},
           {"form", l.form},
           {"sphere", l.sphere},
           {"interval", l.temperature.value},
           {"setpoints", setpoints},
           {"theorem", "proofs/thermal_product.md"}};
    if (!row.exact.empty()) e["exact"] = row.exact;
    if (row.status != "proven") {
      e["lower_bound"] = std::isfinite(l.lower_bound) ? Json(l.lower_bound) : Json(nullptr);
      e["note"] = row.note;
    }
    j[key] = e;
  }
  return j;
}

}  // namespace scalcal::commands
