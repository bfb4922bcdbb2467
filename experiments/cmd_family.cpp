// `scalcal family NAME [--param key=value ...] [--json]`: the exact criteria of a family member
// (closed forms from symbolic/, numbers from them), or closed forms in symbolic parameters.
#include <iostream>
#include <sstream>

#include "experiments/command.hpp"
#include "experiments/json.hpp"
#include "numeric/io/input_error.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/family.hpp"

namespace scalcal::cli {
namespace {

Json number_or_null(const symbolic::ExactValue& v) {
  if (!v.resolved()) return Json(nullptr);
  return Json(v.number());
}

int run(Args& args) {
  const bool json = args.flag("json");
  const auto settings = args.values("param");
  const auto pos = args.positionals();
  if (pos.size() != 1) throw UsageError("expected exactly one family NAME");
  const auto& family = symbolic::find_family(pos[0]);
  const auto params = symbolic::parse_params(family, settings);
  const auto inst = family.instance(params);
  symbolic::ExactCriteria c;
  try {
    c = symbolic::exact_criteria(inst.M, inst.N);
  } catch (const std::invalid_argument&) {
    throw InputError(pos[0], 0, "the information matrix is singular: these parameters cannot identify all nine");
  }
  std::ostringstream n;
  n << inst.N;
  const struct { const char* key; const symbolic::ExactValue* v; } rows[] = {
      {"D", &c.D}, {"A", &c.A}, {"E", &c.E}, {"S", &c.S},
      {"theta_bias", &c.theta_bias}, {"theta_scale", &c.theta_scale}, {"theta_nonorth", &c.theta_nonorth}};
  if (json) {
    Json out = Json::object();
    out.set("family", family.name);
    Json ps = Json::object();
    for (const auto& [k, v] : params) {
      std::ostringstream s;
      s << v;
      ps.set(k, s.str());
    }
    out.set("params", ps);
    if (symbolic::is_number(inst.N)) out.set("positions", Json(static_cast<long long>(GiNaC::ex_to<GiNaC::numeric>(inst.N).to_long())));
    else out.set("positions", n.str());
    for (const auto& r : rows) out.set(r.key, number_or_null(*r.v));
    Json exact = Json::object();
    for (const auto& r : rows) exact.set(r.key, r.v->exact ? r.v->str() : std::string("no closed form (eigenvalue of an irregular block)"));
    out.set("exact", exact);
    out.dump(std::cout);
    std::cout << "\n";
    return 0;
  }
  std::cout << "family " << family.name;
  for (const auto& [k, v] : params) std::cout << " " << k << "=" << v;
  std::cout << "\npositions N = " << n.str() << "\n";
  for (const auto& r : rows) {
    std::cout << "  " << r.key << " = " << (r.v->exact ? r.v->str() : std::string("(no closed form)"));
    if (r.v->resolved()) std::cout << "  ~ " << r.v->number();
    std::cout << "\n";
  }
  return 0;
}

std::string usage() {
  std::string u = "family NAME [--param key=value ...] [--json]   (NAME:";
  for (const auto& f : symbolic::families()) {
    u += " " + f.name;
    if (!f.params.empty()) {
      u += "[";
      for (std::size_t i = 0; i < f.params.size(); ++i) u += (i ? "," : "") + f.params[i].key + "=" + f.params[i].fallback;
      u += "]";
    }
  }
  return u + ")";
}

const Registration reg({"family", usage(),
                        "exact closed forms of D, A, E, S and the thetas for a program family; symbolic values allowed",
                        60, run});

}  // namespace
}  // namespace scalcal::cli
