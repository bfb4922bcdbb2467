// The JSON and the program file of a plan (plan.hpp). JSON keys: program, bench, region (null
// without one), order, resolution_deg, steps (each: step, position (1-based), the mounting under the
// bench's key when it has several, angles_deg or one key per axis, eta, rounding_deg),
// total_travel_deg, remounts, given_order {total_travel_deg, remounts}, travel_saved_deg,
// max_rounding_deg, criteria and criteria_designed (every criterion, thetas), efficiency_lost; a thermal
// plan's setpoints (t_c, first_step, steps), soak_s, dwell_s, travel_deg_per_s and total_s.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "commands/bench/plan.hpp"
#include "commands/bench/thermal_plan.hpp"
#include "commands/core/evaluation_json.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::commands {
namespace {

Json triple(const Vec3& v) { return Json{v(0), v(1), v(2)}; }

// The bench's own settings of one step.
void add_setting(Json& j, const Bench& bench, const BenchSetting& s) {
  const auto& mountings = bench.mountings();
  if (mountings.size() > 1)
    j[std::string(bench.mounting_key())] = mountings[static_cast<std::size_t>(s.mounting)].value;
  const auto& axes = bench.axes();
  if (bench.angles_as_array()) {
    Json a = Json::array();
    for (double x : s.angles) a.push_back(x);
    j["angles_deg"] = a;
  } else {
    for (std::size_t k = 0; k < axes.size(); ++k) j[axes[k].name] = s.angles[k];
  }
}

bool integer_text(const std::string& s, long& value) {
  char* end = nullptr;
  value = s.empty() ? 0 : std::strtol(s.c_str(), &end, 10);
  return !s.empty() && end == s.c_str() + s.size();
}

}  // namespace

Json to_json(const PlanResult& r) {
  Json steps = Json::array();
  for (std::size_t k = 0; k < r.steps.size(); ++k) {
    const PlannedStep& s = r.steps[k];
    Json j{{"step", k + 1}, {"position", s.position + 1}};
    add_setting(j, r.bench, s.setting);
    j["eta"] = triple(s.eta);
    j["rounding_deg"] = s.rounding_deg;
    steps.push_back(j);
  }
  Json designed = Json::object(), as_run = Json::object(), lost = Json::object();
  add_criteria(designed, r.designed);
  add_criteria(as_run, r.as_run);
  for (auto c : kCriteria)
    lost[std::string(criterion_name(c))] = r.efficiency_lost[static_cast<std::size_t>(c.index())];
  Json j{{"program", r.name},
         {"bench", r.bench.text()},
         {"region", r.region ? Json(r.region->text()) : Json(nullptr)},
         {"order", order_name(r.order)},
         {"resolution_deg", r.resolution_deg},
         {"steps", steps},
         {"total_travel_deg", r.travel_deg},
         {"remounts", r.remounts},
         {"given_order", Json{{"total_travel_deg", r.given_travel_deg}, {"remounts", r.given_remounts}}},
         {"travel_saved_deg", r.given_travel_deg - r.travel_deg},
         {"max_rounding_deg", r.max_rounding_deg()}};
  if (!is_default_model(r.model)) j["model"] = std::string(model_name(r.model));
  j["criteria"] = as_run;
  j["criteria_designed"] = designed;
  j["efficiency_lost"] = lost;
  if (!r.setpoints.empty()) {
    Json setpoints = Json::array();
    for (const auto& s : r.setpoints)
      setpoints.push_back(Json{{"t_c", s.celsius}, {"first_step", s.first_step + 1}, {"steps", s.steps}});
    j["setpoints"] = setpoints;
    j["soak_s"] = r.soak_s;
    j["dwell_s"] = r.dwell_s;
    j["travel_deg_per_s"] = kTravelDegPerSecond;
    j["total_s"] = r.total_s;
  }
  return j;
}

PlanFile plan_file(const PlanResult& r) {
  PlanFile f;
  f.program = r.program_as_run();
  ExtraColumn step{"step", {}}, position{"position", {}};
  const auto& mountings = r.bench.mountings();
  // The mounting as its own number (a jig's face) when every mounting is one, else its index with a
  // legend in the comments.
  bool numbered = true;
  long value = 0;
  for (const auto& m : mountings) numbered = numbered && integer_text(m.value, value);
  ExtraColumn mounting{std::string(r.bench.mounting_key()), {}};
  std::vector<ExtraColumn> angles;
  for (const auto& a : r.bench.axes()) angles.push_back(ExtraColumn{a.name, {}});
  for (std::size_t k = 0; k < r.steps.size(); ++k) {
    const PlannedStep& s = r.steps[k];
    step.values.push_back(static_cast<double>(k + 1));
    position.values.push_back(s.position + 1);
    const Mounting& m = mountings[static_cast<std::size_t>(s.setting.mounting)];
    mounting.values.push_back(numbered && integer_text(m.value, value) ? static_cast<double>(value)
                                                                       : static_cast<double>(s.setting.mounting));
    for (std::size_t a = 0; a < angles.size(); ++a) angles[a].values.push_back(s.setting.angles[a]);
  }
  f.columns = {step, position};
  if (mountings.size() > 1) f.columns.push_back(mounting);
  f.columns.insert(f.columns.end(), angles.begin(), angles.end());
  if (!r.celsius.empty()) {
    ExtraColumn celsius{"t_c", {}};
    for (const auto& s : r.steps) celsius.values.push_back(r.celsius[static_cast<std::size_t>(s.position)]);
    f.columns.push_back(celsius);
  }
  if (r.region) f.notes.region = r.region->specs;
  char travel[32];
  std::snprintf(travel, sizeof travel, "%.6g", r.travel_deg);
  f.notes.comments.push_back("plan of " + display_name(r.name) + " on the bench " + r.bench.text() + ", order " +
                             order_name(r.order) + ": " + std::to_string(r.remounts) + " remounts, travel " + travel +
                             " deg");
  if (mountings.size() > 1 && !numbered) {
    std::string legend = std::string(r.bench.mounting_key()) + ":";
    for (std::size_t m = 0; m < mountings.size(); ++m)
      legend += (m ? "," : "") + std::string(" ") + std::to_string(m) + " = " + mountings[m].label;
    f.notes.comments.push_back(legend);
  }
  return f;
}

}  // namespace scalcal::commands
