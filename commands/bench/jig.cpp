// `scalcal jig` (jig.hpp): the search over rotations (numeric/synthesis/mounting.hpp), then what the
// closed forms of symbolic/ decide at the mounting found.
#include "commands/bench/jig.hpp"

#include <cmath>
#include <cstdio>

#include "commands/core/evaluation_json.hpp"
#include "commands/design/gyro_regions.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/synthesis/mounting.hpp"
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"
#include "symbolic/jig_limits.hpp"
#include "symbolic/limits.hpp"

namespace scalcal::commands {
namespace {

std::string jig_names() {
  std::string s;
  for (const auto& f : symbolic::families())
    if (f.group == "jig") s += (s.empty() ? "" : ", ") + f.name.substr(f.name.find(':') + 1);
  return s;
}

const symbolic::Family& jig_family(const std::string& name) {
  const std::string full = name.rfind("jig:", 0) == 0 ? name : "jig:" + name;
  for (const auto& f : symbolic::families())
    if (f.group == "jig" && f.name == full) return f;
  throw InputError(name, 0, "no such jig (known: " + jig_names() + ")");
}

double as_double(const GiNaC::ex& e) { return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e)).to_double(); }

// The nearest exact form of a rotation found numerically: each entry a rational p/q or the square root
// of one (q <= 64), accepted only if the result is exactly orthonormal with determinant 1 and within
// 1e-6 of the numerical one. Then the criterion at that mounting has a closed form.
std::optional<GiNaC::matrix> exact_rotation(const Eigen::Matrix3d& O) {
  GiNaC::matrix X(3, 3);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const double v = O(r, c), sq = v * v;
      bool found = false;
      for (int q = 1; q <= 64 && !found; ++q) {
        const double p = std::round(v * q), p2 = std::round(sq * q);
        if (std::abs(v - p / q) < 1e-6) {
          X(r, c) = GiNaC::numeric(static_cast<long>(p), q);
          found = true;
        } else if (std::abs(sq - p2 / q) < 1e-6 && p2 > 0) {
          X(r, c) = (v < 0 ? -1 : 1) * GiNaC::sqrt(GiNaC::numeric(static_cast<long>(p2), q));
          found = true;
        }
      }
      if (!found) return std::nullopt;
    }
  const GiNaC::matrix XXt = X.mul(X.transpose());
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (!symbolic::is_zero_exact(XXt(r, c) - (r == c ? 1 : 0))) return std::nullopt;
  if (!symbolic::is_zero_exact(X.determinant() - 1)) return std::nullopt;
  return X;
}

// A gyro on a rate table measures each face's normal and, the turn reversed, its antipode (Theorem 24).
// A jig whose faces come in opposite pairs (every printable jig of full rank) gains no direction, and
// every criterion, normalised by N, is the same for the doubled program: the accelerometer's answer.
void gyro_reading(const std::string& jig, const Program& normals, JigResult& r) {
  for (const Vec3& n : normals.positions) {
    bool opposite = false;
    for (const Vec3& m : normals.positions) opposite = opposite || (n + m).norm() < 1e-9;
    if (!opposite)
      throw InputError(jig, 0,
                       words("{instrument gyro}: its faces are not in opposite pairs, so reversed turns would add "
                             "directions; evaluate the program with its antipodes instead"));
  }
  r.instrument = "gyro";
  r.instrument_note =
      "a gyro on a rate table: the faces come in opposite pairs, so a reversed turn measures a direction the jig "
      "already has; every criterion (normalised by N) is the accelerometer's (Theorem 24)";
}

// The numerical search over rotations (the default mounting kept when nothing beats it).
void search(const JigRequest& q, const Program& normals, JigResult& r, const Progress& progress) {
  MountingOptions m;
  m.criterion = q.criterion;
  m.starts = q.starts;
  m.seed = q.seed;
  if (progress) m.progress = [&](int done, int total) { progress("starts", done, total); };
  MountingResult best = best_mounting(normals, m);
  if (!(best.value < r.value_default * (1 - 1e-12))) {  // the default mounting is as good, to precision
    best.orientation.setIdentity();
    best.value = r.value_default;
  }
  r.orientation = best.orientation;
  r.value = best.value;
  r.starts = best.starts;
  r.hits = best.hits;
  r.status = "numerical";
  char buf[160];
  std::snprintf(buf, sizeof buf, "Nelder-Mead over rotations, %d starts, %d within 1e-8 of the best (spread %.1e)",
                best.starts, best.hits, best.spread);
  r.method = buf;
}

// At an exact rotation near the one found, the criterion's closed form; the limit reached there is
// proven optimal whatever the search.
void exact_at_best(const symbolic::Family& family, const symbolic::ParamMap& params, const GiNaC::ex* limit,
                   JigResult& r) {
  const auto X = exact_rotation(r.orientation);
  if (!X) return;
  auto turned = params;
  turned["orientation"] = *X;
  try {
    const auto inst = family.instance(turned);
    const auto exact = symbolic::exact_criteria(inst.M, inst.N);
    const symbolic::ExactValue* v = exact.of(r.criterion);
    if (!(v && v->exact && v->resolved() && std::abs(v->number() / r.value - 1) < 1e-9)) return;
    r.exact = v->str();
    r.orientation_exact = symbolic::param_text(*X);
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) r.orientation(i, k) = as_double((*X)(i, k));
    r.value = v->number();
    r.at_limit = limit && symbolic::is_zero_exact(v->value() - *limit);
  } catch (const std::exception&) {  // no closed form at this mounting: the numbers stand
  }
}

}  // namespace

const CommandTable& jig_table() {
  Option name;
  name.name = "NAME";
  name.kind = OptionKind::positional;
  name.what = "the jig: " + jig_names() + " (with or without jig:)";
  static const CommandTable table{
      "jig",
      "the best way to mount the meter in a printable jig, proven where the closed forms decide",
      62,
      {name, criterion_option(),
       named(integer_option("--starts", 1, 100000,
                            "starts of the search over rotations (the first is the default mounting)", "starts", "64"),
             "K"),
       seed_option(), design_instrument_option(),
       out_option("write the face normals at the best mounting, in the meter's coordinates, as a program CSV"),
       json_option("print one JSON object")}};
  return table;
}

JigRequest jig_request(const Values& v) {
  return {v.text("NAME"), criterion_of(v), static_cast<int>(v.integer("--starts")),
          static_cast<std::uint64_t>(v.integer("--seed")), v.text("--instrument") == "gyro"};
}

JigResult jig(const JigRequest& q, const Progress& progress) {
  const symbolic::Family& family = jig_family(q.name);
  const auto params = symbolic::parse_params(family, {});
  const Program normals = *family.numeric(params);
  JigResult r;
  r.jig = family.name;
  if (q.gyro) gyro_reading(family.name, normals, r);
  r.criterion = q.criterion;
  r.faces = normals.size();
  r.before = evaluate(normals);
  if (!r.before.full_rank())
    throw InputError(family.name, 0,
                     "rank-deficient in every orientation (a rotation keeps the rank): " + rank_deficiency(r.before));
  const symbolic::JigAnalysis facts = symbolic::analyse_jig(family.points(params));
  const symbolic::JigLimitClaim& claim = facts.claim[static_cast<std::size_t>(q.criterion.index())];
  r.claim_status = claim.status, r.claim_reason = claim.reason, r.claim_proven = claim.proven;
  r.invariant = facts.four_design || q.criterion == CriterionKind::D;
  r.value_default = r.value = r.before.value(q.criterion);
  std::optional<GiNaC::ex> limit;
  if (symbolic::has_symbolic_limit(q.criterion)) {
    limit = symbolic::symbolic_limit(q.criterion).value;
    r.limit = as_double(*limit);
    r.limit_exact = symbolic::canonical_text(*limit);
  }
  if (r.invariant) {
    r.status = "proven";
    r.method = facts.four_design ? "a 4-design: every criterion is the same in every orientation"
                                 : "D is the same in every orientation (h(R eta) = T(R) h(eta), det T(R) = 1)";
    const symbolic::ExactValue* v = facts.at_default ? facts.at_default->of(q.criterion) : nullptr;
    if (v && v->exact) r.exact = v->str();
  } else {
    search(q, normals, r, progress);
    exact_at_best(family, params, limit ? &*limit : nullptr, r);
  }
  if (r.at_limit) {
    r.status = "proven";
    r.method = "the value is the limit, below which no program goes (search: " + r.method + ")";
  }
  r.program = mounted(r.orientation, normals);
  r.after = evaluate(r.program);
  return r;
}

Json to_json(const JigResult& r) {
  Json rows = Json::array();
  for (int i = 0; i < 3; ++i)
    rows.push_back(Json::array({r.orientation(i, 0), r.orientation(i, 1), r.orientation(i, 2)}));
  const auto criteria = [](const Evaluation& ev) {
    Json j = Json::object();
    add_criteria(j, erase_model(ev));
    return j;
  };
  Json out{{"jig", r.jig},
           {"criterion", std::string(criterion_name(r.criterion))},
           {"orientation", rows},
           {"value", r.value},
           {"value_default_orientation", r.value_default},
           {"program", program_json(r.program)}};
  out["positions"] = r.faces;
  out["instrument"] = r.instrument;
  if (!r.instrument_note.empty()) out["instrument_note"] = r.instrument_note;
  out["value_status"] = r.status;
  out["method"] = r.method;
  if (!r.exact.empty()) out["exact"] = r.exact;
  if (!r.orientation_exact.empty()) out["orientation_exact"] = r.orientation_exact;
  out["limit"] = r.limit ? Json(*r.limit) : Json(nullptr);
  out["limit_exact"] = r.limit ? Json(r.limit_exact) : Json(nullptr);
  out["ratio"] = r.limit ? Json(r.value / *r.limit) : Json(nullptr);
  out["limit_claim"] = r.claim_status;
  out["limit_claim_proven"] = r.claim_proven;
  out["limit_claim_reason"] = r.claim_reason;
  out["criteria_default"] = criteria(r.before);
  out["criteria_best"] = criteria(r.after);
  if (!r.invariant) {
    out["starts"] = r.starts;
    out["hits"] = r.hits;
  }
  return out;
}

}  // namespace scalcal::commands
