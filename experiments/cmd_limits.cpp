// `scalcal limits [--json]`: the infimum of each normalised criterion over all measures on the
// sphere, derived symbolically (symbolic/limits.hpp), with the moments of an optimal measure.
#include <iostream>
#include <sstream>

#include "experiments/command.hpp"
#include "experiments/json.hpp"
#include "symbolic/limits.hpp"

namespace scalcal::cli {
namespace {

std::string text(const GiNaC::ex& e) {
  std::ostringstream s;
  s << e;
  return s.str();
}

double number(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(); }

int run(Args& args) {
  const bool json = args.flag("json");
  if (!args.positionals().empty()) throw UsageError("limits takes no arguments");
  Json out = Json::object();
  for (auto c : kCriteria) {
    const auto l = symbolic::symbolic_limit(c);
    if (!json) {
      std::cout << criterion_name(c) << " >= " << text(l.value) << " = " << number(l.value) << "   optimal moments: E[x^2] = 1/3, E[x^4] = "
                << text(l.x4) << ", E[x^2 y^2] = " << text(l.b) << ", odd moments and other mixed moments 0\n";
      continue;
    }
    Json moments = Json::object();
    moments.set("E[x^2]", "1/3");
    moments.set("E[x^4]", text(l.x4));
    moments.set("E[x^2 y^2]", text(l.b));
    moments.set("odd", "0");
    Json entry = Json::object();
    entry.set("exact", text(l.value));
    entry.set("value", number(l.value));
    entry.set("moments", moments);
    entry.set("b", number(l.b));
    out.set(std::string(criterion_name(c)), entry);
  }
  if (json) {
    out.dump(std::cout);
    std::cout << "\n";
  }
  return 0;
}

const Registration reg({"limits", "limits [--json]",
                        "exact N -> infinity limits of the normalised D, A, E, S criteria and optimal moments", 61, run});

}  // namespace
}  // namespace scalcal::cli
