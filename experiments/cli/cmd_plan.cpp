// `scalcal plan PROGRAM --bench SPEC [--resolution DEG] [--order travel|remounts|given] [--region SPEC]...
// [--model NAME] [--out FILE] [--json]`: bench settings and a run order (commands/bench/plan.hpp), printed as
// a sheet an operator follows step by step; --out writes the plan as a program file in run order.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "commands/bench/plan.hpp"
#include "commands/bench/thermal_plan.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/output_file.hpp"

namespace scalcal::cli {
namespace {

// Decimals that show the resolution (0.1: one, 0.05: two), four for exact angles.
int decimals(double resolution) {
  if (resolution <= 0) return 4;
  return std::clamp(static_cast<int>(std::ceil(-std::log10(resolution) - 1e-9)), 0, 6);
}

std::string fixed(double v, int places, int width) {
  char s[64];
  std::snprintf(s, sizeof s, "%*.*f", width, places, v == 0 ? 0.0 : v);  // no "-0.0"
  return s;
}

// A time as an operator reads it: 45 s, 12 min 30 s, 45 min, 3 h 05 min.
std::string duration(double seconds) {
  char s[48];
  const long long t = std::llround(seconds), minutes = std::llround(seconds / 60);
  if (t < 60)
    std::snprintf(s, sizeof s, "%lld s", t);
  else if (t < 3600 && t % 60 != 0)
    std::snprintf(s, sizeof s, "%lld min %lld s", t / 60, t % 60);
  else if (t < 3600)
    std::snprintf(s, sizeof s, "%lld min", t / 60);
  else
    std::snprintf(s, sizeof s, "%lld h %02lld min", minutes / 60, minutes % 60);
  return s;
}

// A share below 1e-12 is rounding (the criteria carry about 15 digits): it prints as such, not as a
// number that changes from one CPU to another.
std::string percent(double share) {
  if (std::abs(share) < 1e-12) return "< 1e-10 %";
  char s[32];
  std::snprintf(s, sizeof s, "%.3g %%", 100 * share);
  return s;
}

void print_header(std::ostream& out, const commands::PlanResult& r) {
  out << "plan of " << r.name << " on the bench " << r.bench.text() << " (order " << commands::order_name(r.order)
      << ", resolution "
      << (r.resolution_deg > 0 ? fixed(r.resolution_deg, decimals(r.resolution_deg), 0) + " deg" : "exact")
      << (r.region ? ", region " + r.region->text() : std::string()) << ")\n";
  out << r.steps.size() << " steps, " << r.remounts << (r.remounts == 1 ? " remount" : " remounts")
      << ", the axes travel " << fixed(r.travel_deg, 1, 0) << " deg (the program's own order: " << r.given_remounts
      << " remounts, " << fixed(r.given_travel_deg, 1, 0) << " deg";
  if (r.given_travel_deg > 0 && r.travel_deg < r.given_travel_deg)
    out << "; " << percent(1 - r.travel_deg / r.given_travel_deg) << " less travel";
  out << ")\n";
  if (r.setpoints.empty()) return;
  out << r.setpoints.size() << " set-points from the coldest:";
  for (std::size_t i = 0; i < r.setpoints.size(); ++i) out << (i ? ", " : " ") << fixed(r.setpoints[i].celsius, 1, 0);
  out << " degC; soak " << duration(r.soak_s) << " at each, rest " << fixed(r.dwell_s, 1, 0) << " s on each position\n"
      << "estimated time " << duration(r.total_s) << " (soaks " << duration(r.soak_s * r.setpoints.size()) << ", rests "
      << duration(r.dwell_s * r.steps.size()) << ", travel at " << fixed(commands::kTravelDegPerSecond, 0, 0)
      << " deg/s " << duration(r.travel_deg / commands::kTravelDegPerSecond)
      << (r.remounts ? "; remounts by hand not counted" : "") << ")\n";
}

// The set-point that begins at step k (0-based), or nullptr.
const commands::SetPointRun* setpoint_at(const commands::PlanResult& r, std::size_t k) {
  for (const auto& s : r.setpoints)
    if (static_cast<std::size_t>(s.first_step) == k) return &s;
  return nullptr;
}

void print_steps(std::ostream& out, const commands::PlanResult& r) {
  const auto& mountings = r.bench.mountings();
  const auto& axes = r.bench.axes();
  const bool headings = mountings.size() > 1 && r.bench.remount(BenchSetting{0, {}}, BenchSetting{1, {}});
  const int places = decimals(r.resolution_deg);
  std::string head = "  step  position";
  if (mountings.size() > 1 && !headings) head += "  " + std::string(r.bench.mounting_key()) + std::string(9, ' ');
  for (const auto& a : axes) head += std::string(std::max<std::size_t>(2, 14 - a.name.size()), ' ') + a.name;
  head += "   measures (x, y, z)\n";
  int last = -1;
  for (std::size_t k = 0; k < r.steps.size(); ++k) {
    const commands::PlannedStep& s = r.steps[k];
    const commands::SetPointRun* setpoint = setpoint_at(r, k);
    if (setpoint) {
      out << "\nset-point " << fixed(setpoint->celsius, 1, 0) << " degC: soak " << duration(r.soak_s) << ", then steps "
          << k + 1 << "-" << k + static_cast<std::size_t>(setpoint->steps) << "\n";
      if (headings && s.setting.mounting == last) {
        out << "(still mounted: " << mountings[static_cast<std::size_t>(s.setting.mounting)].label << ")\n" << head;
      } else if (!headings) {
        out << head;
      }
    }
    if (headings && s.setting.mounting != last)
      out << (last < 0 ? "\nmount the meter: " : "\nremount the meter: ")
          << mountings[static_cast<std::size_t>(s.setting.mounting)].label << "\n"
          << head;
    else if (k == 0 && !setpoint)
      out << "\n" << head;
    last = s.setting.mounting;
    char lead[32];
    std::snprintf(lead, sizeof lead, "  %4zu  %8d", k + 1, s.position + 1);
    out << lead;
    if (mountings.size() > 1 && !headings) {
      std::string label = mountings[static_cast<std::size_t>(s.setting.mounting)].label;
      label.resize(std::max<std::size_t>(label.size(), 20), ' ');
      out << "  " << label;
    }
    for (std::size_t a = 0; a < axes.size(); ++a) out << fixed(s.setting.angles[a], places, 14);
    out << "   (" << fixed(s.eta(0), 4, 0) << ", " << fixed(s.eta(1), 4, 0) << ", " << fixed(s.eta(2), 4, 0) << ")\n";
  }
}

void print_criteria(std::ostream& out, const commands::PlanResult& r) {
  out << "\nas run (each position within " << fixed(r.max_rounding_deg(), 4, 0) << " deg of the design):";
  for (auto c : kCriteria) {
    char v[32];
    std::snprintf(v, sizeof v, "%.8g", r.as_run.value(c));
    out << (c.index() ? ", " : " ") << criterion_name(c) << " " << v << " (efficiency lost "
        << percent(r.efficiency_lost[static_cast<std::size_t>(c.index())]) << ")";
  }
  out << "\n";
}

int run(const commands::Values& v) {
  const auto r = commands::plan(commands::plan_request(v), terminal_progress("plan"));
  print_warnings("plan", r.warnings);
  if (v.given("--out")) {
    const commands::PlanFile f = commands::plan_file(r);
    write_program_file(v.text("--out"), f.program, f.columns, f.notes);
  }
  if (v.flag("--json")) {
    print_json(commands::to_json(r));
    return 0;
  }
  std::ostringstream text;
  print_header(text, r);
  print_steps(text, r);
  print_criteria(text, r);
  std::cout << text.str();
  return 0;
}

const Registration reg(commands::plan_table(), run);

}  // namespace
}  // namespace scalcal::cli
