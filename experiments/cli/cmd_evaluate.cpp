// `scalcal evaluate PROGRAM [--region SPEC]... [--out FILE] [--json]`: the criteria of one program,
// as the paper compares them; --out writes the program itself as CSV (any catalogue name becomes a
// file). With --region, positions outside the bench's region are refused, and each criterion gets
// its efficiency against the region's limit.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/evaluation_report.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/output_file.hpp"
#include "experiments/cli/region_option.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/region/region_limit.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  std::string program, out, model = "paper9";
  std::vector<std::string> regions;
  bool json = false;
};

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
      std::snprintf(tilt, sizeof tilt, "%.4g", region.zones.front().tilt_deg(program.positions[static_cast<std::size_t>(i)]));
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

int run(const Options& o) {
  const Program program = resolve_program(o.program);
  const ModelKind model = model_of(o.model);
  if (model != ModelKind::paper9 && !o.regions.empty())
    throw UsageError("evaluate: --region has limits for the paper9 model only (got --model " + o.model + ")");
  const ModelEvaluation ev = evaluate(model, program);
  if (!ev.full_rank()) throw InputError(o.program, 0, rank_deficiency(ev));
  if (ev.condition > kIllConditioned)
    std::cerr << "scalcal evaluate: " << o.program << ": warning: " << ill_conditioning(ev) << "\n";
  Json efficiency;
  std::string region_text;
  std::vector<ExtraColumn> columns;
  if (!o.regions.empty()) {
    const Region region = resolve_region(o.regions, "evaluate");
    refuse_outside(o.program, program, region);
    region_text = region.text();
    columns = region_columns(region, program);
    efficiency = region_efficiency(ev, region);
  }
  if (!o.out.empty()) write_program_file(o.out, program, columns);
  if (o.json) {
    Json j = evaluation_json(ev, program);
    if (!region_text.empty()) {
      j["region"] = region_text;
      j["efficiency"] = efficiency;
    }
    print_json(j);
    return 0;
  }
  print_evaluation(std::cout, o.program, ev);
  if (!region_text.empty()) {
    std::cout << "efficiency on " << region_text << " (limit / value; D as its 9th root):";
    for (auto c : kCriteria) {
      char e[32];
      std::snprintf(e, sizeof e, "%.4f", efficiency[std::string(criterion_name(c))].get<double>());
      std::cout << " " << criterion_name(c) << " " << e;
    }
    std::cout << "\n";
  }
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_positional(app, "PROGRAM", o->program, "a catalogue name (scalcal catalogue) or a CSV file (x,y,z or alpha1_deg,alpha2_deg)");
  add_region_option(app, o->regions);
  add_model(app, o->model);
  add_text(app, "--out", o->out, "FILE", {"also write the program as CSV x,y,z,alpha1_deg,alpha2_deg", "file path"});
  add_switch(app, "--json", o->json, "print one JSON object (the criteria, the program and K)");
  return [o] { return run(*o); };
}

const Registration reg({"evaluate", "evaluate PROGRAM [--model NAME] [--region SPEC]... [--out FILE] [--json]",
                        "criteria D, A, E, S, the RMS errors theta and K of a catalogue program or CSV file", 10,
                        setup});

}  // namespace
}  // namespace scalcal::cli
