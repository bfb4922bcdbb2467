// `scalcal augment` (augment.hpp).
#include "commands/augment.hpp"

#include <cmath>

#include "commands/region_request.hpp"
#include "numeric/program/catalogue.hpp"

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
       out_option("write the whole program (given, then added) as CSV"), json_option("print one JSON object")}};
  return table;
}

AugmentRequest augment_request(const Values& v) {
  AugmentRequest q;
  q.name = v.text("--program");
  q.given = program_of(v, "--program");
  q.add = static_cast<int>(v.integer("--add"));
  q.criterion = criterion_of(v);
  q.model = model_of(v);
  q.regions = v.list("--region");
  return q;
}

AugmentResult augment(const AugmentRequest& q, const Progress&) {
  AugmentResult r;
  r.criterion = q.criterion;
  r.model = q.model;
  r.region = resolve_region(q.regions, r.warnings);
  r.given = q.given.size();
  r.augmented = augment_program(q.given, q.add, q.criterion, r.region, q.model);
  r.columns = region_columns(r.region, r.augmented.program);
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
         {"added", added},
         {"program", program_json(r.augmented.program)}};
  if (r.model != ModelKind::paper9) j["model"] = std::string(model_name(r.model));
  return j;
}

}  // namespace scalcal::commands
