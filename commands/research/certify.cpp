// `scalcal certify` (certify.hpp).
#include "commands/research/certify.hpp"

#include <stdexcept>

#include "commands/core/usage_error.hpp"
#include "commands/core/work_bound.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {

const CommandTable& certify_table() {
  static const CommandTable table{
      "certify",
      "proves that a program attains a limit (an exact program within a radius) or is a strict local optimum "
      "(value enclosed), by interval arithmetic",
      44,
      {program_argument(), criterion_option(kRequired),
       named(
           integer_option("--digits", 30, 400, "working precision of the interval arithmetic", "decimal digits", "60"),
           "P"),
       json_option("print one JSON object")}};
  return table;
}

CertifyRequest certify_request(const Values& v) {
  return {v.text("PROGRAM"), program_of(v), criterion_of(v), static_cast<int>(v.integer("--digits"))};
}

CertifyCommandResult certify(const CertifyRequest& q, const Progress&) {
  if (q.program.size() < 9) throw UsageError("certify: " + q.name + ": a program needs at least 9 positions");
  check_work(std::to_string(q.program.size()) + words(" positions at {digits} ") + std::to_string(q.digits),
             certify_work(q.program.size(), q.digits), "certify a smaller program or at fewer digits");
  CertifyCommandResult r;
  r.criterion = q.criterion;
  r.positions = q.program.size();
  try {
    r.certificate = scalcal::certify(q.program, q.criterion, CertifyOptions{q.digits});
  } catch (const NoKnownLimit& e) {
    throw UsageError(words("certify: {criterion} ") + std::string(criterion_name(q.criterion)) + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw UsageError(q.name + ": " + e.what());
  }
  return r;
}

Json to_json(const CertifyCommandResult& r) {
  const CertifyResult& c = r.certificate;
  Json j{{"criterion", std::string(criterion_name(r.criterion))},
         {"positions", r.positions},
         {"status", std::string(status_text(c.status))},
         {"value", c.value},
         {"limit", c.limit},
         {"method", c.method},
         {"reason", c.reason},
         {"unknowns", c.unknowns},
         {"equations", c.equations},
         {"seconds", c.seconds}};
  j["radius"] = c.radius.empty() ? Json(nullptr) : Json(c.radius);
  j["enclosure"] = r.local() ? Json::array({c.enclosure_lo, c.enclosure_hi}) : Json(nullptr);
  if (r.local()) j["enclosure_digits"] = c.enclosure_digits;
  return j;
}

}  // namespace scalcal::commands
