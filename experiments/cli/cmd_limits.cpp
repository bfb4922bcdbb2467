// `scalcal limits [--json]`: the infimum of each normalised criterion over all measures on the
// sphere, derived symbolically (symbolic/limits.hpp), with the moments of an optimal measure.
#include <iostream>
#include <sstream>
#include <string>
#include <memory>

#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/limits.hpp"

namespace scalcal::cli {
namespace {

double number(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(); }

int run(bool json) {
  using symbolic::canonical_text;
  Json out = Json::object();
  for (auto c : kCriteria) {
    const auto l = symbolic::symbolic_limit(c);
    if (!json) {
      // The decimal only where it says something the exact form does not (not "E >= 12 = 12").
      const std::string exact = canonical_text(l.value);
      std::ostringstream decimal;
      decimal << number(l.value);
      std::cout << criterion_name(c) << " >= " << exact << (decimal.str() == exact ? "" : " = " + decimal.str())
                << "   optimal moments: E[x^2] = 1/3, E[x^4] = " << canonical_text(l.x4)
                << ", E[x^2 y^2] = " << canonical_text(l.b) << ", odd moments and other mixed moments 0\n";
      continue;
    }
    out[std::string(criterion_name(c))] =
        Json{{"exact", canonical_text(l.value)},
             {"value", number(l.value)},
             {"moments", Json{{"E[x^2]", "1/3"},
                              {"E[x^4]", canonical_text(l.x4)},
                              {"E[x^2 y^2]", canonical_text(l.b)},
                              {"odd", "0"}}},
             {"b", number(l.b)}};
  }
  if (json) print_json(out);
  return 0;
}

Runner setup(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  add_switch(app, "--json", *json, "print one JSON object keyed by criterion");
  return [json] { return run(*json); };
}

const Registration reg({"limits", "limits [--json]",
                        "exact N -> infinity limits of the normalised D, A, E, S criteria and optimal moments", 61,
                        setup});

}  // namespace
}  // namespace scalcal::cli
