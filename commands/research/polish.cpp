// `scalcal polish` (polish.hpp).
#include "commands/research/polish.hpp"

#include <stdexcept>

#include "commands/core/work_bound.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"

namespace scalcal::commands {

const CommandTable& polish_table() {
  static const CommandTable table{
      "polish",
      "a program polished to P digits by Newton's method in MPFR on its first-order conditions",
      43,
      {program_argument(), criterion_option(kRequired),
       named(
           integer_option("--digits", 1, 1000, "significant digits of the polished value", "significant digits", "50"),
           "P"),
       out_option("write the polished program as CSV x,y,z,alpha1_deg,alpha2_deg"),
       json_option("print one JSON object")}};
  return table;
}

PolishRequest polish_request(const Values& v) {
  return {v.text("PROGRAM"), program_of(v), criterion_of(v), static_cast<int>(v.integer("--digits"))};
}

PolishCommandResult polish(const PolishRequest& q, const Progress&) {
  const Evaluation ev = evaluate(q.program);
  if (!ev.full_rank()) throw InputError(q.name, 0, rank_deficiency(ev));
  check_work(std::to_string(q.program.size()) + words(" positions at {digits} ") + std::to_string(q.digits),
             polish_work(q.program.size(), q.digits), "polish fewer positions or to fewer digits");
  PolishCommandResult r;
  r.criterion = q.criterion;
  r.positions = q.program.size();
  try {
    r.polished = scalcal::polish(q.program, q.criterion, PolishOptions{q.digits, 40});
  } catch (const std::invalid_argument& e) {
    throw InputError(q.name, 0, e.what());
  }
  if (!r.polished.converged())
    r.warnings.push_back({q.name, "the polish did not converge (residual " + std::to_string(r.polished.residual) +
                                      "); value_digits keeps " + std::to_string(r.polished.digits) + " digits"});
  r.second_order = second_order(r.polished, q.criterion);
  return r;
}

Json to_json(const PolishCommandResult& r) {
  const PolishResult& p = r.polished;
  return Json{{"criterion", std::string(criterion_name(r.criterion))},
              {"positions", r.positions},
              {"value_digits", p.value_digits},
              {"residual", p.residual},
              {"digits", p.digits},
              {"iterations", p.summary.iterations},
              {"converged", p.converged()},
              {"second_order", r.second_order.text},
              {"second_order_reason", r.second_order.reason},
              {"program", program_json(p.program)}};
}

}  // namespace scalcal::commands
