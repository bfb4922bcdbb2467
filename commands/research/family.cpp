// `scalcal family` (family.hpp).
#include "commands/research/family.hpp"

#include "commands/core/common_options.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "symbolic/criteria.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"
#include "symbolic/model_moments.hpp"

namespace scalcal::commands {
namespace {

// " octahedral[a=1,e=0,d=1] rotation[k=6,phase=0] jig:{cube,...}[orientation=identity]"
std::string family_names() {
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

symbolic::ExactCriteria exact_of(const FamilyRequest& q, const symbolic::FamilyInstance& inst) {
  const bool paper9 = model_supports(q.model, ModelCapability::criteria_native);
  const int P = model_parameters(q.model);
  if (!paper9 && !inst.moment)
    throw InputError(q.name, 0,
                     words("the family gives only the paper's H^T H (no moment function), so {model} ") +
                         std::string(model_name(q.model)) +
                         " cannot be evaluated: give FamilyInstance a MomentFunction");
  try {
    return paper9 ? symbolic::exact_criteria(inst.M, inst.N)
                  : symbolic::exact_criteria(symbolic::model_moment_matrix(q.model, inst.moment), inst.N,
                                             symbolic::model_groups(q.model));
  } catch (const std::invalid_argument&) {
    throw InputError(
        q.name, 0,
        "the information matrix is singular: these parameters cannot identify all " +
            (paper9 ? std::string("nine")
                    : std::to_string(P) + words(" parameters of {model} ") + std::string(model_name(q.model))));
  } catch (const InputError&) {
    throw;
  } catch (const std::runtime_error& e) {  // GiNaC's: e.g. a nested radical under a symbolic rotation
    throw InputError(
        q.name, 0,
        std::string("no closed form for these symbolic parameters (GiNaC: ") + e.what() + "); give numbers instead");
  }
}

ExactRow row_of(const std::string& key, const symbolic::ExactValue& v) {
  ExactRow r{key, v.exact, v.exact ? v.str() : std::string(), std::nullopt};
  if (v.resolved()) r.number = v.number();
  return r;
}

}  // namespace

const CommandTable& family_table() {
  Option name;
  name.name = "NAME";
  name.kind = OptionKind::positional;
  name.what = "the family:" + family_names();
  Option params = text_option("--param", "KEY=VALUE", "a parameter of the family, a number or a symbol (repeatable)",
                              "positions for multiplicities, degrees for a phase");
  params.kind = OptionKind::repeated;
  params.fallback_text = "the family's own, listed above";
  static const CommandTable table{"family",
                                  "exact closed forms of " + criterion_names_text() +
                                      " and the thetas for a program family; symbolic values allowed",
                                  60,
                                  {name, params, model_option(), json_option("print one JSON object")}};
  return table;
}

FamilyRequest family_request(const Values& v) { return {v.text("NAME"), v.list("--param"), model_of(v)}; }

FamilyResult family(const FamilyRequest& q) {
  const auto& fam = symbolic::find_family(q.name);
  const auto params = symbolic::parse_params(fam, q.params);
  symbolic::FamilyInstance inst;
  try {
    inst = fam.instance(params);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const InputError*>(&e)) throw;
    throw InputError(
        q.name, 0,
        std::string("no closed form for these symbolic parameters (GiNaC: ") + e.what() + "); give numbers instead");
  }
  const symbolic::ExactCriteria c = exact_of(q, inst);
  FamilyResult r;
  r.family = fam.name;
  for (const auto& [k, v] : params) r.params.emplace_back(k, symbolic::param_text(v));
  r.model = q.model;
  r.positions = symbolic::canonical_text(inst.N);
  if (symbolic::is_number(inst.N)) {
    r.positions_integer = GiNaC::is_a<GiNaC::numeric>(inst.N) && GiNaC::ex_to<GiNaC::numeric>(inst.N).is_integer();
    r.positions_value = GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(inst.N)).to_double();
  }
  // A criterion without a closed form here (E's eigenvalue of a block that does not split, for a symbolic
  // orientation) is a row that says so, not a missing line.
  for (CriterionKind k : kCriteria)
    r.rows.push_back(c.of(k) ? row_of(std::string(criterion_name(k)), *c.of(k))
                             : ExactRow{std::string(criterion_name(k)), false, std::string(), std::nullopt});
  const std::pair<const char*, const symbolic::ExactValue*> thetas[] = {{"theta_bias", &c.theta_bias},
                                                                        {"theta_scale", &c.theta_scale},
                                                                        {"theta_nonorth", &c.theta_nonorth},
                                                                        {"theta_cubic", &c.theta_cubic}};
  for (const auto& [key, v] : thetas)
    if (!v->candidates.empty()) r.rows.push_back(row_of(key, *v));  // only the groups the model has
  return r;
}

Json to_json(const FamilyResult& r) {
  Json ps = Json::object();
  for (const auto& [k, v] : r.params) ps[k] = v;
  // positions is always the exact text; positions_value the number, null when N is symbolic.
  Json out{{"family", r.family}, {"params", ps}, {"positions", r.positions}};
  if (!is_default_model(r.model)) out["model"] = std::string(model_name(r.model));
  out["positions_value"] = !r.positions_value    ? Json(nullptr)
                           : r.positions_integer ? Json(static_cast<long>(*r.positions_value))
                                                 : Json(*r.positions_value);
  for (const auto& row : r.rows) out[row.key] = row.number ? Json(*row.number) : Json(nullptr);
  Json exact = Json::object();
  for (const auto& row : r.rows)
    exact[row.key] = row.exact ? row.text : std::string("no closed form (eigenvalue of an irregular block)");
  out["exact"] = exact;
  return out;
}

}  // namespace scalcal::commands
