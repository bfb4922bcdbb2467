// `scalcal evaluate` (evaluate.hpp).
#include "commands/design/evaluate.hpp"

#include <filesystem>
#include <stdexcept>

#include "commands/core/common_options.hpp"
#include "commands/core/evaluation_json.hpp"
#include "commands/core/region_request.hpp"
#include "commands/core/usage_error.hpp"
#include "commands/design/gyro_regions.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/region/region_limit.hpp"

namespace scalcal::commands {

const CommandTable& evaluate_table() {
  static const CommandTable table{
      "evaluate",
      "the criteria (" + criterion_names_text() + "), the RMS errors theta and K of a catalogue program or CSV file",
      10,
      {program_argument(), model_or_thermal_option(), temperature_option(), region_option(), design_instrument_option(),
       tolerance_option(),
       out_option("also write the program as CSV x,y,z,alpha1_deg,alpha2_deg (and its region line)"),
       json_option("print one JSON object (the criteria, the program and K)")}};
  return table;
}

EvaluateRequest evaluate_request(const Values& v) {
  EvaluateRequest q;
  q.name = v.text("PROGRAM");
  q.thermal = parse_thermal_model(v.text("--model"));
  if (v.given("--temperature")) q.temperature = parse_temperature_range(v.text("--temperature"));
  if (q.thermal) {
    if (v.program) throw UsageError("evaluate: a thermal program is a CSV file with columns x,y,z,t_c, not an array");
    if (!q.temperature)
      throw UsageError(words("evaluate: {model} ") + q.thermal->name() +
                       words(" needs {temperature T1..T2} (degrees Celsius)"));
    q.model = q.thermal->base;
    q.regions = v.list("--region");
    // A catalogue name is a program without set-points: say so rather than fail to open a file of that name.
    if (!std::filesystem::exists(q.name) && named_program(q.name))
      throw UsageError("evaluate: " + q.name + words(" is a catalogue program without temperatures; {model} ") +
                       q.thermal->name() + " takes a CSV file with columns x,y,z,t_c, as optimize writes for it");
    q.thermal_program = read_thermal_program_csv(q.name);
    return q;
  }
  if (q.temperature)
    throw UsageError(words("evaluate: {temperature} needs a thermal model, {model BASE+Tk} (e.g. paper9+T3)"));
  q.program = program_of(v);
  q.model = model_of(v);
  // --instrument gyro reverses turns on the regions given here; a program file's own region line
  // (optimize --instrument gyro writes it) holds both directions already.
  q.regions = v.program ? v.list("--region") : regions_for(v.list("--region"), q.name, q.warnings);
  q.regions_from_file = !v.given("--region") && !q.regions.empty();
  if (v.given("--region")) q.regions = instrument_regions(v, q.regions);
  q.tolerance_deg = v.number("--tolerance");
  return q;
}

EvaluateResult evaluate(const EvaluateRequest& q, const Progress& progress) {
  if (q.thermal) {
    EvaluateResult r;
    r.name = q.name;
    r.warnings = q.warnings;
    std::optional<Region> region;
    if (!q.regions.empty()) {
      if (!model_supports(q.thermal->base, ModelCapability::region_limits))
        throw region_limits_refusal("evaluate", q.thermal->name());
      region = resolve_region(q.regions, r.warnings);
      Program positions;
      for (const auto& e : q.thermal_program.positions) positions.positions.push_back(e);
      refuse_outside(q.name, positions, *region, q.tolerance_deg);
    }
    r.thermal = evaluate_thermal(q.name, q.thermal_program, *q.thermal, *q.temperature, region, progress);
    r.warnings.insert(r.warnings.end(), r.thermal->warnings.begin(), r.thermal->warnings.end());
    return r;
  }
  EvaluateResult r;
  r.warnings = q.warnings;
  // A model without region limits is judged on the sphere: --region sphere restricts nothing, and a program
  // file's region line (which optimize writes) is said and set aside; a restricted --region is refused.
  std::vector<std::string> regions = q.regions;
  if (!model_supports(q.model, ModelCapability::region_limits) && !regions.empty()) {
    if (!is_sphere(regions)) {
      if (!q.regions_from_file) throw region_limits_refusal("evaluate", model_name(q.model));
      r.warnings.push_back({q.name, "its region line (" + specs_text(regions) +
                                        ") is set aside: region limits exist for the " +
                                        models_supporting(ModelCapability::region_limits) + " model only, so " +
                                        std::string(model_name(q.model)) + " is judged without efficiencies"});
    }
    regions.clear();
  }
  r.name = q.name;
  r.program = q.program;
  r.evaluation = scalcal::evaluate(q.model, q.program);
  if (!r.evaluation.full_rank()) throw InputError(q.name, 0, rank_deficiency(r.evaluation));
  if (r.evaluation.condition > kIllConditioned) r.warnings.push_back({q.name, ill_conditioning(r.evaluation)});
  if (regions.empty()) return r;
  r.region = resolve_region(regions, r.warnings);
  refuse_outside(q.name, q.program, *r.region, q.tolerance_deg);
  r.columns = region_columns(*r.region, q.program);
  for (auto c : kCriteria) {
    if (progress)
      progress("the " + std::string(criterion_name(c)) + " limit on " + r.region->text(), c.index(), kCriterionCount);
    const auto i = static_cast<std::size_t>(c.index());
    r.limits[i] = reported_limit(c, q.model, r.region);  // none: no known limit for this criterion
    if (r.limits[i])
      r.efficiency[i] = efficiency(c, r.limits[i]->statement.value, r.evaluation.value(c), r.evaluation.parameters);
  }
  return r;
}

Json to_json(const EvaluateResult& r) {
  if (r.thermal) return to_json(*r.thermal);
  Json j = evaluation_json(r.evaluation, r.program);
  if (r.region) {
    j["region"] = r.region->text();
    Json e = Json::object(), l = Json::object();
    for (auto c : kCriteria) {
      const auto i = static_cast<std::size_t>(c.index());
      e[std::string(criterion_name(c))] = r.efficiency[i] ? Json(*r.efficiency[i]) : Json(nullptr);
      l[std::string(criterion_name(c))] = r.limits[i] ? to_json(*r.limits[i]) : Json(nullptr);
    }
    j["efficiency"] = e;
    j["limits"] = l;
  }
  return j;
}

}  // namespace scalcal::commands
