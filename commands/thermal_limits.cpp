// A thermal model's limits (thermal_limits.hpp): the base model's proven sphere limit times the
// interval's optimal value, exact where symbolic/thermal_limits.hpp has the interval's closed form.
#include "commands/thermal_limits.hpp"

#include <cmath>
#include <cstdio>

#include "commands/common_options.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"
#include "symbolic/thermal_limits.hpp"

namespace scalcal::commands {
namespace {

// The base model's sphere limit: value and exact text ("" where none is proven).
std::pair<double, std::string> sphere_limit(ModelKind model, CriterionKind c) {
  if (model == ModelKind::paper9) {
    if (!symbolic::has_symbolic_limit(c)) return {NAN, ""};
    const auto l = symbolic::symbolic_limit(c);
    return {GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(l.value)).to_double(), symbolic::canonical_text(l.value)};
  }
  const auto l = stated_limit(model, criterion_name(c));
  if (!l) return {NAN, ""};
  return {l->value, std::string(l->exact)};
}

std::string power(const std::string& base, int exponent) {
  const bool plain = base.find_first_not_of("0123456789") == std::string::npos;
  const std::string b = plain ? base : "(" + base + ")";
  return exponent == 1 ? b : b + "^" + std::to_string(exponent);
}

std::string exact_form(CriterionKind c, const ThermalModel& m, const std::string& s, const std::string& one) {
  const int k = m.degree, P = m.base_parameters();
  const bool full = static_cast<int>(m.drifting().size()) == P;
  if (c == CriterionKind::D)
    return full ? power(s, k + 1) + " * " + power(one, P)
                : power(s, 1) + " * " + power("27", k) + " * " + power(one, 3);
  if (c == CriterionKind::A && !full) return "9 * " + power(one, 1) + " + " + power(s, 1) + " - 9";
  return power(s, 1) + " * " + power(one, 1);
}

}  // namespace

ThermalLimitsResult thermal_limits(const ThermalModel& model, const TemperatureRange& range) {
  ThermalLimitsResult r{model, range, {}};
  for (CriterionKind c : kCriteria) {
    ThermalLimitRow row;
    row.criterion = c;
    const auto [s, s_exact] = sphere_limit(model.base, c);
    row.limit = thermal_limit(c, model, s);
    if (!row.limit) {
      row.note = !std::isfinite(s) ? "the base model has no known limit for this criterion"
                 : static_cast<int>(model.drifting().size()) < model.base_parameters()
                     ? "Theorem 25 gives D and A only when only the biases drift; optimize finds programs numerically"
                     : "no thermal form of this criterion (numeric/thermal/information_criteria.hpp)";
      r.rows.push_back(row);
      continue;
    }
    const GiNaC::ex one = symbolic::interval_factor_exact(c, model.degree);
    if (!one.is_zero() && !s_exact.empty()) {
      row.status = "proven";
      row.exact = exact_form(c, model, s_exact, symbolic::canonical_text(one));
    } else {
      row.status = "numerical";
      char text[160];
      std::snprintf(text, sizeof text,
                    "the interval's factor found numerically; no design does better than %.10g (convexity bound on "
                    "a grid of 20001 temperatures)",
                    row.limit->lower_bound);
      row.note = text;
    }
    r.rows.push_back(row);
  }
  return r;
}

Json to_json(const ThermalLimitsResult& r) {
  Json j{{"model", r.model.name()},
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
      e["lower_bound"] = l.lower_bound;
      e["note"] = row.note;
    }
    j[key] = e;
  }
  return j;
}

}  // namespace scalcal::commands
