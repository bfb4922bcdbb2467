// `scalcal family NAME [--param key=value ...] [--model NAME] [--json]`: the exact criteria of a
// family member (closed forms from symbolic/, numbers from them), or closed forms in symbolic
// parameters, for the paper's model or any registered model (its moment matrix from the family's
// moments). Every expression prints through symbolic::canonical_text, so equal runs print equal bytes.
#include <iostream>
#include <memory>
#include <vector>

#include "experiments/cli/command.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/io/input_error.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"
#include "symbolic/model_moments.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  std::string name;
  std::vector<std::string> params;
  std::string model = "paper9";
  bool json = false;
};

Json number_or_null(const symbolic::ExactValue& v) { return v.resolved() ? Json(v.number()) : Json(nullptr); }

Json positions_value(const GiNaC::ex& N) {
  if (!symbolic::is_number(N)) return nullptr;
  if (GiNaC::is_a<GiNaC::numeric>(N) && GiNaC::ex_to<GiNaC::numeric>(N).is_integer())
    return GiNaC::ex_to<GiNaC::numeric>(N).to_long();
  return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(N)).to_double();
}

int run(const Options& o) {
  const auto& family = symbolic::find_family(o.name);
  const auto params = symbolic::parse_params(family, o.params);
  symbolic::FamilyInstance inst;
  try {
    inst = family.instance(params);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e)) throw;
    throw InputError(o.name, 0, std::string("no closed form for these symbolic parameters (GiNaC: ") + e.what() +
                                    "); give numbers instead");
  }
  const ModelKind model = model_of(o.model);
  const bool paper9 = model == ModelKind::paper9;
  const int P = model_parameters(model);
  if (!paper9 && !inst.moment)
    throw InputError(o.name, 0, "the family gives only the paper's H^T H (no moment function), so --model " +
                                    o.model + " cannot be evaluated: give FamilyInstance a MomentFunction");
  symbolic::ExactCriteria c;
  try {
    c = paper9 ? symbolic::exact_criteria(inst.M, inst.N)
               : symbolic::exact_criteria(symbolic::model_moment_matrix(model, inst.moment), inst.N,
                                          symbolic::model_groups(model));
  } catch (const std::invalid_argument&) {
    throw InputError(o.name, 0,
                     "the information matrix is singular: these parameters cannot identify all " +
                         (paper9 ? std::string("nine") : std::to_string(P) + " parameters of --model " + o.model));
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {  // GiNaC's: e.g. a nested radical under a symbolic rotation
    throw InputError(o.name, 0, std::string("no closed form for these symbolic parameters (GiNaC: ") + e.what() +
                                    "); give numbers instead");
  }
  const std::string n = symbolic::canonical_text(inst.N);
  struct Row {
    const char* key;
    const symbolic::ExactValue* v;
  };
  std::vector<Row> rows = {{"D", &c.D}, {"A", &c.A}, {"E", &c.E}, {"S", &c.S}};
  const Row thetas[] = {{"theta_bias", &c.theta_bias},
                        {"theta_scale", &c.theta_scale},
                        {"theta_nonorth", &c.theta_nonorth},
                        {"theta_cubic", &c.theta_cubic}};
  for (const Row& t : thetas)
    if (!t.v->candidates.empty()) rows.push_back(t);  // only the groups the model has
  if (o.json) {
    Json ps = Json::object();
    for (const auto& [k, v] : params) ps[k] = symbolic::param_text(v);
    // positions is always the exact text; positions_value the number, null when N is symbolic.
    Json out{{"family", family.name}, {"params", ps}, {"positions", n}};
    if (!paper9) out["model"] = o.model;
    out["positions_value"] = positions_value(inst.N);
    for (const auto& r : rows) out[r.key] = number_or_null(*r.v);
    Json exact = Json::object();
    for (const auto& r : rows)
      exact[r.key] = r.v->exact ? r.v->str() : std::string("no closed form (eigenvalue of an irregular block)");
    out["exact"] = exact;
    print_json(out);
    return 0;
  }
  std::cout << "family " << family.name;
  for (const auto& [k, v] : params) std::cout << " " << k << "=" << symbolic::param_text(v);
  if (!paper9) std::cout << " (model " << o.model << ", D = N^" << P << " det K)";
  std::cout << "\npositions N = " << n << "\n";
  for (const auto& r : rows) {
    std::cout << "  " << r.key << " = " << (r.v->exact ? r.v->str() : std::string("(no closed form)"));
    if (r.v->resolved()) std::cout << "  ~ " << r.v->number();
    std::cout << "\n";
  }
  return 0;
}

std::string names() {
  std::string u, jigs;
  for (const auto& f : symbolic::families()) {
    if (f.group == "jig") {  // twelve and more: one entry for all, their parameter once
      jigs += (jigs.empty() ? "" : ",") + f.name.substr(4);
      continue;
    }
    u += " " + f.name;
    if (!f.params.empty()) {
      u += "[";
      for (std::size_t i = 0; i < f.params.size(); ++i)
        u += (i ? "," : "") + f.params[i].key + "=" + f.params[i].fallback;
      u += "]";
    }
  }
  return jigs.empty() ? u : u + " jig:{" + jigs + "}[orientation=identity]";
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_positional(app, "NAME", o->name, "the family:" + names());
  add_repeatable(app, "--param", o->params, "KEY=VALUE",
                 {"a parameter of the family, a number or a symbol (repeatable)",
                  "positions for multiplicities, degrees for a phase", "the family's own, listed above"});
  add_model(app, o->model);
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"family",
                        "family NAME [--param key=value ...] [--model NAME] [--json]   (NAME:" + names() + ")",
                        "exact closed forms of D, A, E, S and the thetas for a program family; symbolic values allowed",
                        60, setup});

}  // namespace
}  // namespace scalcal::cli
