// `scalcal optimize` (optimize.hpp).
#include "commands/design/optimize.hpp"

#include <cmath>
#include <stdexcept>

#include "commands/core/region_request.hpp"
#include "commands/core/usage_error.hpp"
#include "commands/core/work_bound.hpp"
#include "commands/design/gyro_regions.hpp"
#include "commands/design/thermal_optimize.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/criteria/model_evaluation.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/region/region_synthesis.hpp"

namespace scalcal::commands {
namespace {

void check(const OptimizeRequest& q) {
  const SynthesisOptions& o = q.synthesis;
  if (o.positions < model_parameters(o.model))
    throw UsageError(words("optimize: {positions} ") + std::to_string(o.positions) + " is below the " +
                     std::to_string(model_parameters(o.model)) + words(" parameters of {model} ") +
                     std::string(model_name(o.model)));
  // The message as it always read while one model had both (paper9); with other models it says which has which.
  const bool regions = !is_sphere(q.regions) && !model_supports(o.model, ModelCapability::region_limits),
             digits = q.digits > 0 && !model_supports(o.model, ModelCapability::polish_digits);
  const std::string with_regions = models_supporting(ModelCapability::region_limits),
                    with_digits = models_supporting(ModelCapability::polish_digits);
  if (regions || digits)
    throw UsageError("optimize: " +
                     (with_regions == with_digits ? words("{region} and {digits} work with the ") + with_regions
                      : regions                   ? words("{region} works with the ") + with_regions
                                                  : words("{digits} works with the ") + with_digits) +
                     words(" model only (got {model} ") + std::string(model_name(o.model)) + ")");
}

// --from: start 0 is that program, and N its size.
void start_from(const OptimizeRequest& q, SynthesisOptions& o) {
  if (q.from.empty()) {
    if (o.positions == 0) throw UsageError(words("{positions N} is required (or {from PROGRAM}, whose size it takes)"));
    return;
  }
  Program start = q.start ? *q.start : resolve_program(q.from);
  if (o.positions != 0 && o.positions != start.size())
    throw UsageError(words("{positions} ") + std::to_string(o.positions) + words(" but {from} ") +
                     display_name(q.from) + " has " + std::to_string(start.size()) + " positions");
  if (start.size() < kOptimizePositions.lo || start.size() > kOptimizePositions.hi)
    throw UsageError(words("{from} ") + display_name(q.from) + " has " + std::to_string(start.size()) +
                     " positions; optimize takes " + std::to_string(kOptimizePositions.lo) + ".." +
                     std::to_string(kOptimizePositions.hi));
  if (!q.regions.empty()) throw UsageError(words("{from} starts the search on the sphere; it does not take {region}"));
  // A start that cannot identify every parameter has no gradient: the search would stay there and
  // report an infinite value as its optimum.
  const ModelEvaluation ev = evaluate(o.model, start);
  if (!ev.full_rank())
    throw InputError(display_name(q.from), 0,
                     rank_deficiency(ev) + words("; {from} needs a start of full rank (or give {positions N} alone)"));
  o.positions = start.size();
  o.first_start = std::move(start);
}

}  // namespace

const CommandTable& optimize_table() {
  static const CommandTable table{
      "optimize",
      "the optimal program for a criterion (Newton/Ipopt multistart, optional high-precision polish)",
      40,
      {named(integer_option("--positions", kOptimizePositions.lo, kOptimizePositions.hi,
                            "number of positions N (at least the model's number of parameters)", "positions", "0",
                            words("required, unless {from} gives it")),
             "N"),
       positions_option(text_option("--from", "PROGRAM",
                                    "start 0 of the multistart is this program (a catalogue name, a family member "
                                    "such as jig:cuboctahedron, or a CSV file); N is its size",
                                    "catalogue name or file path")),
       criterion_option(), model_or_thermal_option(), temperature_option(), region_option(), design_instrument_option(),
       named(number_option("--margin", 0, 10,
                           "design every position this far inside the region's boundaries (the efficiency stays "
                           "judged against the region itself)",
                           "degrees", "0"),
             "DEG"),
       starts_option(), seed_option(), threads_option(),
       named(integer_option("--digits", kPolishDigits.lo, kPolishDigits.hi,
                            "polish the optimum to this many digits in MPFR", "significant digits", "0",
                            "none (no polish)"),
             "P"),
       local_option(),
       out_option(
           words("write the program (the polished one with {digits}) as CSV x,y,z,alpha1_deg,alpha2_deg, after a "
                 "'# region:' line with {region}")),
       json_option("print one JSON object")}};
  return table;
}

OptimizeRequest optimize_request(const Values& v) {
  OptimizeRequest q;
  q.synthesis.positions = static_cast<int>(v.integer("--positions"));
  q.from = v.text("--from");
  if (v.given("--from")) q.start = program_of(v, "--from");
  q.synthesis.criterion = criterion_of(v);
  q.thermal = parse_thermal_model(v.text("--model"));
  q.synthesis.model = q.thermal ? q.thermal->base : model_of(v);
  if (v.given("--temperature")) q.temperature = parse_temperature_range(v.text("--temperature"));
  q.regions = instrument_regions(v, v.list("--region"));
  q.margin_deg = v.number("--margin");
  q.synthesis.starts = static_cast<int>(v.integer("--starts"));
  q.synthesis.seed = static_cast<std::uint64_t>(v.integer("--seed"));
  q.synthesis.threads = static_cast<int>(v.integer("--threads"));
  q.digits = static_cast<int>(v.integer("--digits"));
  q.synthesis.local = local_solver_of(v);
  return q;
}

OptimizeResult optimize(const OptimizeRequest& q, const Progress& progress) {
  if (q.thermal || q.temperature) {
    if (!q.thermal)
      throw UsageError(words("optimize: {temperature} needs a thermal model, {model BASE+Tk} (e.g. paper9+T3)"));
    if (!q.temperature)
      throw UsageError(words("optimize: {model} ") + q.thermal->name() +
                       words(" needs {temperature T1..T2} (degrees Celsius)"));
    OptimizeRequest sphere = q;
    sphere.thermal.reset();
    sphere.temperature.reset();
    auto t = std::make_shared<ThermalOptimizeResult>(thermal_optimize(sphere, *q.thermal, *q.temperature, progress));
    OptimizeResult r = t->sphere;
    r.warnings = t->warnings;
    r.thermal = t;
    return r;
  }
  OptimizeResult r;
  SynthesisOptions opt = q.synthesis;
  start_from(q, opt);
  OptimizeRequest checked = q;
  checked.synthesis.positions = opt.positions;
  check(checked);
  r.criterion = opt.criterion;
  r.model = opt.model;
  r.positions = opt.positions;
  if (progress) opt.progress = [&](int done, int total) { progress("starts", done, total); };
  // --region sphere restricts nothing: a model without region limits (check() refused any other) is on the sphere.
  if (!q.regions.empty() && model_supports(opt.model, ModelCapability::region_limits))
    r.region = resolve_region(q.regions, r.warnings);
  const bool restricted = r.region && !r.region->is_sphere();
  if (q.margin_deg > 0 && !restricted)
    throw UsageError(words("{margin} moves positions inside a restricted {region}'s boundaries; the sphere has none"));
  if (q.margin_deg > 0) {
    // The inset region is where the positions go: it must be resolved as the region itself is (cap:5
    // inset by 4.999 degrees is a cap of 0.001 degrees, where every program is rank-deficient).
    r.designed_on = inset_region(*r.region, q.margin_deg);
    check_conditioning(*r.designed_on, r.warnings, "--margin");
  }
  if (restricted && q.digits > 0)
    throw InputError(option_word("digits"), 0,
                     words("the polish solves the unconstrained optimality conditions; it cannot keep positions inside "
                           "{region} ") +
                         r.region->text());
  if (q.digits > 0)
    check_work(words("{positions} ") + std::to_string(opt.positions) + words(" {digits} ") + std::to_string(q.digits),
               polish_work(opt.positions, q.digits), "polish fewer positions or to fewer digits");
  r.synthesis = restricted ? synthesize_on_region(opt, r.designed_on ? *r.designed_on : *r.region) : synthesize(opt);
  if (!std::isfinite(r.synthesis.value))
    throw InputError(option_word("region"), 0,
                     "no start reached a program of full rank on " +
                         (r.designed_on ? r.designed_on->text()
                          : r.region    ? r.region->text()
                                        : std::string("the sphere")) +
                         " in double precision (its " + std::string(criterion_name(opt.criterion)) + " is infinite)");
  if (!r.synthesis.summary.converged())
    r.warnings.push_back({"", r.synthesis.summary.message + " (" + r.synthesis.local_solver + " multistart)"});
  if (q.digits > 0) {
    if (progress) progress("polishing at " + std::to_string(q.digits) + " digits", 0, 0);
    r.polished = polish(r.synthesis.program, opt.criterion, PolishOptions{q.digits, 40});
    if (!r.polished->converged())
      r.warnings.push_back({"", "the polish did not converge (residual " + std::to_string(r.polished->residual) +
                                    "); value_digits keeps " + std::to_string(r.polished->digits) + " digits"});
  }
  // The polished program is the better one (its rounding to double is as close to the optimum as
  // double allows): it is the one written and printed.
  r.program = r.polished ? r.polished->program : r.synthesis.program;
  // Its value is the one reported beside it: the polished program's in double (the same evaluation as evaluate's),
  // not the multistart's, which can be further off (E at N = 12: 12.000000000016222, the polished program's
  // 12.00000000000001).
  r.value = r.polished ? evaluate(opt.model, r.program).value(opt.criterion) : r.synthesis.value;
  if (r.region) r.columns = region_columns(*r.region, r.program);
  const int P = model_parameters(opt.model);
  if (!model_supports(opt.model, ModelCapability::criteria_native) || r.region) {
    if (r.region && progress)
      progress("the " + std::string(criterion_name(opt.criterion)) + " limit on " + r.region->text(), 0, 0);
    r.limit_statement = reported_limit(opt.criterion, opt.model, r.region);  // none: no known limit
    if (r.limit_statement) r.limit = r.limit_statement->statement.value;
  }
  if (r.limit) r.efficiency = efficiency(opt.criterion, *r.limit, r.value, P);
  return r;
}

Json to_json(const OptimizeResult& r) {
  if (r.thermal) return to_json(*r.thermal);
  const SynthesisResult& s = r.synthesis;
  Json j{{"criterion", std::string(criterion_name(r.criterion))},
         {"positions", r.positions},
         {"value", r.value},
         {"program", program_json(r.program)},
         {"starts", s.starts},
         {"stopping", s.stopping},
         {"hits", s.hits},
         {"distinct", s.distinct},
         {"seconds", s.seconds},
         {"local_solver", s.local_solver},
         {"confirmed", s.summary.converged()}};
  if (!is_default_model(r.model)) {
    j["model"] = std::string(model_name(r.model));
    if (r.limit) {
      j["limit"] = *r.limit;
      j["limit_statement"] = to_json(*r.limit_statement);
      j["efficiency"] = *r.efficiency;
    }
  } else if (r.region && r.limit) {
    j["region"] = r.region->text();
    j["limit"] = *r.limit;
    j["limit_statement"] = to_json(*r.limit_statement);
    j["efficiency"] = *r.efficiency;
  }
  if (r.designed_on) j["designed_on"] = r.designed_on->text();
  if (r.polished) {
    j["value_digits"] = r.polished->value_digits;
    j["residual"] = r.polished->residual;
    j["converged"] = r.polished->converged();
    j["iterations"] = r.polished->summary.iterations;
  }
  return j;
}

}  // namespace scalcal::commands
