// `scalcal plan` (plan.hpp).
#include "commands/bench/plan.hpp"

#include <cmath>
#include <cstdio>

#include "commands/bench/thermal_plan.hpp"
#include "commands/core/common_options.hpp"
#include "commands/core/region_request.hpp"
#include "commands/core/usage_error.hpp"
#include "commands/core/work_bound.hpp"
#include "numeric/bench/rounding.hpp"
#include "numeric/criteria/efficiency.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {
namespace {

std::string short_number(double v, const char* format = "%.4g") {
  char s[48];
  std::snprintf(s, sizeof s, format, v);
  return s;
}

std::string vector_text(const Vec3& x) {
  return "(" + short_number(x(0)) + ", " + short_number(x(1)) + ", " + short_number(x(2)) + ")";
}

// Every setting of every position; InputError naming up to ten positions the bench cannot reach.
std::vector<std::vector<BenchSetting>> reachable(const PlanRequest& q, const Bench& bench) {
  std::vector<std::vector<BenchSetting>> choices;
  std::vector<int> beyond;
  for (int i = 0; i < q.program.size(); ++i) {
    choices.push_back(bench.settings(q.program.positions[static_cast<std::size_t>(i)]));
    if (choices.back().empty()) beyond.push_back(i);
  }
  if (beyond.empty()) return choices;
  std::string list;
  for (std::size_t k = 0; k < beyond.size() && k < 10; ++k)
    list += (k ? ", " : "") + std::to_string(beyond[k] + 1) + " " +
            vector_text(q.program.positions[static_cast<std::size_t>(beyond[k])]);
  if (beyond.size() > 10) list += ", ...";
  throw InputError(q.name, 0,
                   std::to_string(beyond.size()) + " of " + std::to_string(q.program.size()) +
                       " positions are beyond the reach of the bench " + bench.text() + ": position " + list);
}

// The plan's settings on the resolution grid, inside the region; InputError naming a position that
// no grid setting keeps there.
std::vector<PlannedStep> on_grid(const PlanRequest& q, const Bench& bench, const RunPlan& run, const Region& region) {
  std::vector<PlannedStep> steps;
  for (const RunStep& s : run.steps) {
    const auto rounded = round_setting(bench, s.setting, q.resolution_deg, region);
    if (!rounded)
      throw InputError(q.name, 0,
                       "position " + std::to_string(s.position + 1) + ": no setting of " + bench.text() + " on its " +
                           short_number(q.resolution_deg) +
                           "-degree grid (within two steps of the exact angles) "
                           "measures a position inside the region " +
                           region.text());
    PlannedStep p{s.position, *rounded, bench.position(*rounded), 0};
    const Vec3& designed = q.program.positions[static_cast<std::size_t>(s.position)];
    p.rounding_deg = std::atan2(designed.cross(p.eta).norm(), designed.dot(p.eta)) / kDegree;
    steps.push_back(std::move(p));
  }
  return steps;
}

// A resolution that moves the positions out of the design: the share of D efficiency the rounding
// costs (all of it when the program as run is rank-deficient), beyond --max-loss, is refused with both
// figures. D, the determinant (as its P-th root), is smooth in the positions: a bench's own resolution
// costs it little (0.9 % at 0.5 degrees on an ill-conditioned program whose E lost 6.9 %), while a grid
// that moves positions away costs it much (15 degrees on tilt:40: 66 %); A, E and S are printed.
void refuse_loss(const PlanRequest& q, const PlanResult& r) {
  const CriterionKind D = CriterionKind::D;
  if (!std::isfinite(r.designed.value(D))) return;  // a design without a D of its own has none to lose
  const double lost = r.as_run.full_rank() ? r.efficiency_lost[static_cast<std::size_t>(D.index())] : 1.0;
  if (!(lost * 100 > q.max_loss * 100 + 1e-12) && !std::isnan(lost)) return;
  throw UsageError(
      words("{resolution} ") + short_number(q.resolution_deg) + " moves the positions out of the design: as run " +
      (r.as_run.full_rank() ? "" : "the program is rank-deficient and ") + "it loses " +
      short_number(std::isnan(lost) ? 100 : 100 * lost, "%.3g") + " % of its D efficiency (positions up to " +
      short_number(r.max_rounding_deg(), "%.3g") + words(" deg from the design), beyond {max-loss} ") +
      short_number(100 * q.max_loss, "%.3g") + words(" %: a finer {resolution}, or {max-loss 100} to plan it anyway"));
}

RunPlan as_run_plan(const std::vector<PlannedStep>& steps) {
  RunPlan r;
  for (const auto& s : steps) r.steps.push_back(RunStep{s.position, s.setting});
  return r;
}

}  // namespace

const char* order_name(RunOrder order) {
  switch (order) {
    case RunOrder::travel:
      return "travel";
    case RunOrder::remounts:
      return "remounts";
    case RunOrder::given:
      return "given";
  }
  return "?";
}

double PlanResult::max_rounding_deg() const {
  double m = 0;
  for (const auto& s : steps) m = std::max(m, s.rounding_deg);
  return m;
}

Program PlanResult::program_as_run() const {
  Program p;
  for (const auto& s : steps) p.positions.push_back(s.eta);
  return p;
}

const CommandTable& plan_table() {
  Option bench = text_option("--bench", "SPEC", "the bench: " + bench_syntaxes(), "none", kRequired);
  bench.why_bad = [](const std::string& spec) -> std::string {
    try {
      parse_bench(spec);
    } catch (const InputError& e) {
      return e.reason();
    }
    return "";
  };
  static const CommandTable table{
      "plan",
      "bench settings for each position of a program and the order to run them (fewest remounts, then least travel)",
      57,
      {program_argument(), bench,
       named(number_option("--resolution", 0, 90,
                           "set every angle to a multiple of this, never leaving the region (0: the exact angles)",
                           "degrees", "0"),
             "DEG"),
       named(
           number_option("--max-loss", 0, 100,
                         words("the largest share of the design's D efficiency that rounding to {resolution} may cost: "
                               "beyond it plan stops and says so (100: plan whatever it costs)"),
                         "percent", "5"),
           "PERCENT"),
       choice_option("--order", {"travel", "remounts", "given"},
                     "travel: fewest remounts, then least travel of the axes; remounts: fewest remounts, the given "
                     "order within each mounting; given: the program's order",
                     "travel"),
       region_option(), model_option(),
       named(number_option("--soak", 0, 10080,
                           "a thermal program (a temperature column): minutes the meter soaks at each set-point "
                           "before its positions are measured",
                           "minutes", "30"),
             "MIN"),
       named(number_option("--dwell", 0, 86400,
                           words("a thermal program: seconds at rest on each position (simulate's {dwell})"), "seconds",
                           "5"),
             "S"),
       out_option("write the plan as a program file in run order (step, position, mounting, angles, a thermal "
                  "program's t_c; region line)"),
       json_option("print one JSON object")}};
  return table;
}

PlanRequest plan_request(const Values& v) {
  PlanRequest q;
  q.name = v.text("PROGRAM");
  q.program = program_of(v);
  q.bench = v.text("--bench");
  q.resolution_deg = v.number("--resolution");
  q.max_loss = v.number("--max-loss") / 100;
  const std::string order = v.text("--order");
  q.order = order == "given" ? RunOrder::given : order == "remounts" ? RunOrder::remounts : RunOrder::travel;
  q.regions = v.program ? v.list("--region") : regions_for(v.list("--region"), q.name, q.warnings);
  q.model = model_of(v);
  if (!v.program) q.celsius = program_temperatures(q.name);
  if (q.celsius.empty())
    for (const char* option : {"--soak", "--dwell"})
      if (v.given(option))
        throw UsageError(std::string(option) + " belongs to a thermal program (a temperature column t_c, " +
                         "temperature, temp or t), and " + q.name + " has none");
  if (!q.celsius.empty() && q.celsius.size() != static_cast<std::size_t>(q.program.size()))
    throw InputError(q.name, 0, "its temperatures and positions are not one per row");
  q.soak_s = 60 * v.number("--soak");
  q.dwell_s = v.number("--dwell");
  return q;
}

PlanResult plan(const PlanRequest& q, const Progress& progress) {
  if (!q.celsius.empty()) return plan_thermal(q, progress);
  PlanResult r(parse_bench(q.bench));
  r.name = q.name;
  r.warnings = q.warnings;
  r.order = q.order;
  r.resolution_deg = q.resolution_deg;
  r.model = q.model;
  const Region region = q.regions.empty() ? sphere_region() : resolve_region(q.regions, r.warnings);
  if (!q.regions.empty()) r.region = region;
  const auto choices = reachable(q, r.bench);
  if (q.order == RunOrder::travel) {  // the other orders are linear in the positions
    double settings = 0;
    for (const auto& c : choices) settings += static_cast<double>(c.size());
    check_work(std::to_string(q.program.size()) + " positions on " + r.bench.text() + " (order travel)",
               plan_work(q.program.size(), settings / std::max<std::size_t>(1, choices.size())),
               words("plan the program in parts, or {order} remounts"));
  }
  if (progress) progress("ordering", 0, 0);
  RunPlan given = run_in_order(r.bench, choices, [&] {
    std::vector<int> o(choices.size());
    for (std::size_t i = 0; i < o.size(); ++i) o[i] = static_cast<int>(i);
    return o;
  }());
  const RunPlan planned = plan_run(r.bench, choices, q.order);
  const auto given_steps = on_grid(q, r.bench, given, region);
  r.steps = on_grid(q, r.bench, planned, region);
  RunPlan run = as_run_plan(r.steps), given_run = as_run_plan(given_steps);
  count_travel(r.bench, run);
  count_travel(r.bench, given_run);
  // Rounding moves each axis by less than a step: when it makes a near tie go the other way, the
  // given order is run (a plan never travels more than the program's own order).
  if (given_run.remounts < run.remounts ||
      (given_run.remounts == run.remounts && given_run.travel_deg < run.travel_deg)) {
    r.steps = given_steps;
    run = given_run;
  }
  r.travel_deg = run.travel_deg;
  r.remounts = run.remounts;
  r.given_travel_deg = given_run.travel_deg;
  r.given_remounts = given_run.remounts;
  judge_rounding(q, r);
  if (!r.as_run.full_rank())
    r.warnings.push_back({q.name, "the program as run is rank-deficient (its criteria are infinite)"});
  return r;
}

void judge_rounding(const PlanRequest& q, PlanResult& r) {
  r.designed = scalcal::evaluate(q.model, q.program);
  r.as_run = scalcal::evaluate(q.model, r.program_as_run());
  const int P = model_parameters(q.model);
  for (auto c : kCriteria) {
    const double before = r.designed.value(c), after = r.as_run.value(c);
    r.efficiency_lost[static_cast<std::size_t>(c.index())] =
        std::isfinite(before) && std::isfinite(after) ? 1 - efficiency(c, before, after, P) : NAN;
  }
  refuse_loss(q, r);
}

}  // namespace scalcal::commands
