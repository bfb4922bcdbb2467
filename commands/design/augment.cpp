// `scalcal augment` (augment.hpp).
#include "commands/design/augment.hpp"

#include <cmath>
#include <stdexcept>

#include "commands/core/region_request.hpp"
#include "commands/core/work_bound.hpp"
#include "commands/design/limits_statement.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/region/region_limit.hpp"

namespace scalcal::commands {

const CommandTable& augment_table() {
  Option program = text_option("--program", "FILE", "the program the lab has: a catalogue name or a CSV file",
                               "file path", kRequired);
  program.takes_positions = true;
  static const CommandTable table{
      "augment",
      "add the K positions that improve a program most, inside the bench's region",
      55,
      {program, named(integer_option("--add", 1, 1000, "how many positions to add", "positions", kRequired), "K"),
       criterion_option(), model_option(), region_option(),
       named(integer_option("--starts", 1, 1000,
                            "starts of the joint optimisation of the added positions (start 0 from the greedy "
                            "exchange, the others from random grid candidates)",
                            "starts", "8"),
             "K"),
       seed_option(), threads_option(),
       out_option("write the whole program (given, then added) as CSV, with its region line"),
       json_option("print one JSON object")}};
  return table;
}

AugmentRequest augment_request(const Values& v) {
  AugmentRequest q;
  q.name = v.text("--program");
  q.given = program_of(v, "--program");
  q.add = static_cast<int>(v.integer("--add"));
  q.criterion = criterion_of(v);
  q.model = model_of(v);
  q.regions = v.program ? v.list("--region") : regions_for(v.list("--region"), q.name, q.warnings);
  q.polish.starts = static_cast<int>(v.integer("--starts"));
  q.polish.seed = static_cast<std::uint64_t>(v.integer("--seed"));
  q.polish.threads = static_cast<int>(v.integer("--threads"));
  return q;
}

AugmentResult augment(const AugmentRequest& q, const Progress& progress) {
  AugmentResult r;
  r.warnings = q.warnings;
  r.criterion = q.criterion;
  r.model = q.model;
  r.region = resolve_region(q.regions, r.warnings);
  r.given = q.given.size();
  check_work(std::to_string(q.given.size()) + " + " + std::to_string(q.add) + " positions",
             augment_work(q.given.size() + q.add), "augment a smaller program");
  r.augmented = augment_program(q.given, q.add, q.criterion, r.region, q.model, q.polish);
  r.columns = region_columns(r.region, r.augmented.program);
  if (model_supports(q.model, ModelCapability::region_limits) && std::isfinite(r.augmented.value)) {
    try {
      if (progress) progress("the " + std::string(criterion_name(q.criterion)) + " limit on " + r.region.text(), 0, 0);
      r.limit = limit_value(q.criterion, r.region);
      r.efficiency = efficiency(q.criterion, *r.limit, r.augmented.value);
    } catch (const std::invalid_argument&) {  // no known limit for this criterion
    }
  } else if (r.region.is_sphere() && std::isfinite(r.augmented.value)) {
    // Another model on the sphere: its stated limit, as optimize and sweep judge it (none where it states none).
    if (const auto stated = reported_limit(q.criterion, q.model, std::nullopt)) {
      r.limit = stated->statement.value;
      r.efficiency = efficiency(q.criterion, *r.limit, r.augmented.value, model_parameters(q.model));
    }
  }
  return r;
}

Json to_json(const AugmentResult& r) {
  const auto value = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  Json added = Json::array();
  for (const Vec3& x : r.augmented.added) added.push_back(Json{x.x(), x.y(), x.z()});
  Json j{{"criterion", std::string(criterion_name(r.criterion))},
         {"region", r.region.text()},
         {"value_before", value(r.augmented.value_before)},
         {"value", value(r.augmented.value)},
         {"value_greedy_start", value(r.augmented.value_greedy)},
         {"starts", r.augmented.starts},
         {"best_start", r.augmented.best_start},
         {"limit", r.limit ? Json(*r.limit) : Json(nullptr)},
         {"efficiency", r.efficiency ? Json(*r.efficiency) : Json(nullptr)},
         {"added", added},
         {"program", program_json(r.augmented.program)}};
  if (!is_default_model(r.model)) j["model"] = std::string(model_name(r.model));
  return j;
}

}  // namespace scalcal::commands
