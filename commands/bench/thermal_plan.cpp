// A thermal program's plan: set-points from the coldest, each planned on the bench, and its time (thermal_plan.hpp).
#include "commands/bench/thermal_plan.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "numeric/io/csv_table.hpp"
#include "numeric/thermal/thermal_program.hpp"

namespace scalcal::commands {

std::vector<double> program_temperatures(const std::string& program) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(program, ec)) return {};
  const CsvTable table = read_csv(program);
  for (const std::string& name : kTemperatureColumns)
    if (table.has(name)) return read_thermal_program_csv(program).celsius;
  return {};
}

PlanResult plan_thermal(const PlanRequest& q, const Progress& progress) {
  // Set-points to 0.5 degC, coldest first; each one's rows in the program's order.
  std::map<long long, std::vector<int>> groups;
  for (int i = 0; i < q.program.size(); ++i)
    groups[std::llround(2 * q.celsius[static_cast<std::size_t>(i)])].push_back(i);
  PlanRequest whole = q;
  whole.celsius.clear();
  whole.order = RunOrder::given;
  whole.max_loss = 1;                    // the rounding's cost is judged per set-point below
  PlanResult r = plan(whole, progress);  // the program's own order: the reference for travel and remounts
  r.given_travel_deg = r.travel_deg;
  r.given_remounts = r.remounts;
  r.order = q.order;
  r.celsius = q.celsius;
  r.steps.clear();  // its warnings stay: the region's, and a rank the pooled positions lack in any order
  for (const auto& [key, rows] : groups) {
    PlanRequest part = q;
    part.celsius.clear();
    part.program.positions.clear();
    double sum = 0;
    for (int i : rows) {
      part.program.positions.push_back(q.program.positions[static_cast<std::size_t>(i)]);
      sum += q.celsius[static_cast<std::size_t>(i)];
    }
    SetPointRun s{sum / static_cast<double>(rows.size()), static_cast<int>(r.steps.size()),
                  static_cast<int>(rows.size())};
    char label[64];
    std::snprintf(label, sizeof label, " at %g degC", s.celsius);
    part.name = q.name + label;
    PlanResult p = plan(part, progress);
    // Reversed, a set-point's steps travel as far and remount as often; run them the way that starts nearer
    // to where the last set-point ended (the same positions at every set-point then end and start alike).
    if (!r.steps.empty() && !p.steps.empty()) {
      const auto junction = [&](const PlannedStep& next) {
        RunPlan hop;
        hop.steps = {RunStep{0, r.steps.back().setting}, RunStep{0, next.setting}};
        count_travel(r.bench, hop);
        return kRemountCostDeg * hop.remounts + hop.travel_deg;
      };
      if (junction(p.steps.back()) < junction(p.steps.front())) std::reverse(p.steps.begin(), p.steps.end());
    }
    for (PlannedStep step : p.steps) {
      step.position = rows[static_cast<std::size_t>(step.position)];
      r.steps.push_back(step);
    }
    r.setpoints.push_back(s);
  }
  RunPlan run;
  for (const auto& s : r.steps) run.steps.push_back(RunStep{s.position, s.setting});
  count_travel(r.bench, run);
  r.travel_deg = run.travel_deg;
  r.remounts = run.remounts;
  judge_rounding(q, r);
  r.soak_s = q.soak_s;
  r.dwell_s = q.dwell_s;
  r.total_s = q.soak_s * static_cast<double>(r.setpoints.size()) + q.dwell_s * static_cast<double>(r.steps.size()) +
              r.travel_deg / kTravelDegPerSecond;
  return r;
}

}  // namespace scalcal::commands
