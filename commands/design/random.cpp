// `scalcal random` (random.hpp).
#include "commands/design/random.hpp"

#include <cmath>

#include "commands/core/region_request.hpp"
#include "commands/core/usage_error.hpp"
#include "commands/core/work_bound.hpp"
#include "numeric/criteria/registry.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/region/region_sampler.hpp"

namespace scalcal::commands {

const CommandTable& random_table() {
  static const CommandTable table{
      "random",
      "the best of R uniform random programs (the paper's dashed line), on all cores",
      41,
      {named(
           integer_option("--positions", 3, 100000, "number of positions N (at least the model's number of parameters)",
                          "positions", kRequired),
           "N"),
       named(integer_option("--count", 1, 1000000000LL, "random programs drawn", "programs", kRequired), "R"),
       seed_option(), criterion_option(), model_option(), region_option(), threads_option(),
       out_option("write the best program as CSV x,y,z,alpha1_deg,alpha2_deg (and its region line)"),
       json_option("print one JSON object")}};
  return table;
}

RandomRequest random_request(const Values& v) {
  RandomRequest q;
  q.positions = static_cast<int>(v.integer("--positions"));
  q.count = v.integer("--count");
  q.seed = static_cast<std::uint64_t>(v.integer("--seed"));
  q.criterion = criterion_of(v);
  q.model = model_of(v);
  q.regions = v.list("--region");
  q.threads = static_cast<int>(v.integer("--threads"));
  return q;
}

RandomResult random_programs(const RandomRequest& q, const Progress&) {
  if (q.positions < model_parameters(q.model))
    throw UsageError(words("random: {positions} ") + std::to_string(q.positions) + " is below the " +
                     std::to_string(model_parameters(q.model)) + words(" parameters of {model} ") +
                     std::string(model_name(q.model)));
  check_work(
      words("{count} ") + std::to_string(q.count) + words(" at {positions} ") + std::to_string(q.positions),
      random_search_work(q.count, q.positions, model_parameters(q.model), criterion_scoring_seconds(q.criterion)),
      words("lower {count} or {positions}, or run several seeds one after another"));
  RandomResult r;
  r.request = q;
  PositionSampler sampler;
  if (!q.regions.empty()) {
    const Region region = resolve_region(q.regions, r.warnings);
    if (!region.is_sphere()) {
      sampler = region_sampler(region);
      r.region = region.text();
    }
  }
  r.search = random_search(q.positions, q.count, q.criterion, q.seed, q.threads, sampler, q.model);
  // No program with a finite value: the "best" would be a placeholder of zero vectors, not a program.
  if (!std::isfinite(r.search.best))
    throw UsageError(
        "none of the " + std::to_string(q.count) + " random programs of " + std::to_string(q.positions) + " positions" +
        (r.region.empty() ? "" : " on " + r.region) + " has a finite " + std::string(criterion_name(q.criterion)) +
        words(" (each is rank-deficient in double precision): draw more ({count}), more positions, or a wider "
              "region"));
  return r;
}

Json to_json(const RandomResult& r) {
  Json j{{"best", r.search.best},
         {"count", r.search.count},
         {"program", program_json(r.search.program)},
         {"seconds", r.search.seconds}};
  if (!r.region.empty()) j["region"] = r.region;
  if (!is_default_model(r.request.model)) j["model"] = std::string(model_name(r.request.model));
  return j;
}

}  // namespace scalcal::commands
