#include "experiments/cli/evaluate_report.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "experiments/cli/command.hpp"
#include "experiments/cli/evaluation_report.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/cli/region_option.hpp"
#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/region/region_limit.hpp"

namespace scalcal::cli {
namespace {

// Names up to ten positions outside the region, 1-based as in the file, with their tilt from the
// nearest zone's axis when the region has zones.
void refuse_outside(const std::string& name, const Program& program, const Region& region) {
  std::vector<int> outside;
  for (int i = 0; i < program.size(); ++i)
    if (!region.contains(program.positions[static_cast<std::size_t>(i)])) outside.push_back(i);
  if (outside.empty()) return;
  std::string list;
  for (std::size_t k = 0; k < outside.size() && k < 10; ++k) {
    const int i = outside[k];
    list += (k ? ", " : "") + std::to_string(i + 1);
    if (!region.zones.empty()) {
      char tilt[32];
      std::snprintf(tilt, sizeof tilt, "%.4g",
                    region.zones.front().tilt_deg(program.positions[static_cast<std::size_t>(i)]));
      list += std::string(" (tilt ") + tilt + " deg)";
    }
  }
  if (outside.size() > 10) list += ", ...";
  throw InputError(name, 0,
                   std::to_string(outside.size()) + " of " + std::to_string(program.size()) +
                       " positions are outside the region " + region.text() + ": position " + list);
}

// limit / value per criterion, D as (limit / value)^(1/P) so that every efficiency reads as the
// fraction of the ideal measurement effort.
Json region_efficiency(const ModelEvaluation& ev, const Region& region) {
  Json out = Json::object();
  for (auto c : kCriteria) {
    if (progress_enabled()) std::cerr << "evaluate: the " << criterion_name(c) << " limit on " << region.text() << "\n";
    out[std::string(criterion_name(c))] = efficiency(c, limit_value(c, region), ev.value(c));
  }
  return out;
}

}  // namespace

Report evaluate_report(const EvaluateRequest& o) {
  const Program& program = o.program;
  const ModelKind model = o.model;
  if (model != ModelKind::paper9 && !o.regions.empty())
    throw UsageError("evaluate: --region has limits for the paper9 model only (got --model " +
                     std::string(model_name(model)) + ")");
  const ModelEvaluation ev = evaluate(model, program);
  if (!ev.full_rank()) throw InputError(o.name, 0, rank_deficiency(ev));
  if (ev.condition > kIllConditioned)
    std::cerr << "scalcal evaluate: " << o.name << ": warning: " << ill_conditioning(ev) << "\n";
  Json efficiency;
  std::string region_text;
  std::vector<ExtraColumn> columns;
  if (!o.regions.empty()) {
    const Region region = resolve_region(o.regions, "evaluate");
    refuse_outside(o.name, program, region);
    region_text = region.text();
    columns = region_columns(region, program);
    efficiency = region_efficiency(ev, region);
  }
  if (!o.out.empty()) write_program_file(o.out, program, columns);
  Report report;
  report.json = evaluation_json(ev, program);
  if (!region_text.empty()) {
    report.json["region"] = region_text;
    report.json["efficiency"] = efficiency;
  }
  std::ostringstream text;
  print_evaluation(text, o.name, ev);
  if (!region_text.empty()) {
    text << "efficiency on " << region_text << " (limit / value; D as its 9th root):";
    for (auto c : kCriteria) {
      char e[32];
      std::snprintf(e, sizeof e, "%.4f", efficiency[std::string(criterion_name(c))].get<double>());
      text << " " << criterion_name(c) << " " << e;
    }
    text << "\n";
  }
  report.text = text.str();
  return report;
}

}  // namespace scalcal::cli
