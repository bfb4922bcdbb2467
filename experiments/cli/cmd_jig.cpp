// `scalcal jig NAME [--criterion C] [--starts K] [--seed S] [--json]`: the best way to mount the meter
// in a printable jig (any family of group "jig"): the rotation of the meter in the jig that minimises
// the criterion, as the meter's axes in jig coordinates, with the criteria before and after. What the
// closed forms decide (symbolic/jig_limits.hpp) is reported as proven; the rest as numerical.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "experiments/cli/command.hpp"
#include "experiments/cli/evaluation_report.hpp"
#include "experiments/cli/json_output.hpp"
#include "experiments/cli/options.hpp"
#include "experiments/cli/synthesis_cli.hpp"
#include "numeric/criteria/evaluation.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/synthesis/mounting.hpp"
#include "symbolic/family.hpp"
#include "symbolic/jig_limits.hpp"
#include "symbolic/limits.hpp"

namespace scalcal::cli {
namespace {

struct Options {
  std::string name, criterion = "D";
  int starts = 64;
  std::uint64_t seed = 1;
  bool json = false;
};

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

Json rows_json(const Eigen::Matrix3d& O) {
  Json rows = Json::array();
  for (int r = 0; r < 3; ++r) rows.push_back(Json::array({O(r, 0), O(r, 1), O(r, 2)}));
  return rows;
}

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

Json criteria_json(const Evaluation& ev) {
  return Json{{"D", ev.D}, {"A", ev.A}, {"E", ev.E}, {"S", ev.S}, {"theta_bias", ev.theta_bias},
              {"theta_scale", ev.theta_scale}, {"theta_nonorth", ev.theta_nonorth}};
}

int run(const Options& o) {
  const symbolic::Family& family = jig_family(o.name);
  const CriterionKind c = criterion_of(o.criterion);
  const auto params = symbolic::parse_params(family, {});
  const auto normals_exact = family.points(params);
  const Program normals = *family.numeric(params);
  const Evaluation before = evaluate(normals);
  if (!before.full_rank())
    throw InputError(family.name, 0, "rank-deficient in every orientation (a rotation keeps the rank): " +
                                         rank_deficiency(before));
  const symbolic::JigAnalysis facts = symbolic::analyse_jig(normals_exact);
  const int ci = c == CriterionKind::D ? 0 : c == CriterionKind::A ? 1 : c == CriterionKind::E ? 2 : 3;
  const symbolic::JigLimitClaim& claim = facts.claim[ci];
  const bool invariant = facts.four_design || c == CriterionKind::D;
  MountingResult best;
  best.value_default = before.value(c);
  best.value = best.value_default;
  std::string status, how;
  if (invariant) {
    status = "proven";
    how = facts.four_design ? "a 4-design: every criterion is the same in every orientation"
                            : "D is the same in every orientation (h(R eta) = T(R) h(eta), det T(R) = 1)";
  } else {
    MountingOptions m;
    m.criterion = c;
    m.starts = o.starts;
    m.seed = o.seed;
    if (progress_enabled())
      m.progress = [](int done, int total) { std::cerr << "\rstart " << done << "/" << total << std::flush; };
    best = best_mounting(normals, m);
    if (m.progress) std::cerr << "\n";
    if (!(best.value < best.value_default * (1 - 1e-12))) {  // the default mounting is as good, to precision
      best.orientation.setIdentity();
      best.value = best.value_default;
    }
    status = "numerical";
    char buf[160];
    std::snprintf(buf, sizeof buf, "Nelder-Mead over rotations, %d starts, %d within 1e-8 of the best (spread %.1e)",
                  best.starts, best.hits, best.spread);
    how = buf;
  }
  const symbolic::SymbolicLimit limit = symbolic::symbolic_limit(c);
  std::string exact_best, exact_orientation;
  bool at_limit = false;  // the exact value at the mounting found is the limit: optimal, whatever the search
  if (!invariant)
    if (const auto X = exact_rotation(best.orientation)) {
      auto turned = params;
      turned["orientation"] = *X;
      try {
        const auto inst = family.instance(turned);
        const auto exact = symbolic::exact_criteria(inst.M, inst.N);
        const symbolic::ExactValue* v = exact.of(c);
        if (v && v->exact && v->resolved() && std::abs(v->number() / best.value - 1) < 1e-9) {
          exact_best = v->str();
          exact_orientation = symbolic::param_text(*X);
          for (int r = 0; r < 3; ++r)
            for (int k = 0; k < 3; ++k) best.orientation(r, k) = as_double((*X)(r, k));
          best.value = v->number();
          at_limit = symbolic::is_zero_exact(v->value() - limit.value);
        }
      } catch (const std::exception&) {  // no closed form at this mounting: the numbers stand
      }
    }
  if (at_limit) {
    status = "proven";
    how = "the value is the limit, below which no program goes (search: " + how + ")";
  }
  const Program program = mounted(best.orientation, normals);
  const Evaluation after = evaluate(program);
  const double limit_value = as_double(limit.value);
  const std::string exact_value =
      invariant && facts.at_default && facts.at_default->of(c)->exact ? facts.at_default->of(c)->str() : "";
  if (o.json) {
    Json out{{"jig", family.name},
             {"criterion", std::string(criterion_name(c))},
             {"orientation", rows_json(best.orientation)},
             {"value", best.value},
             {"value_default_orientation", best.value_default},
             {"program", program_json(program)}};
    out["positions"] = normals.size();
    out["value_status"] = status;
    out["method"] = how;
    if (!exact_value.empty()) out["exact"] = exact_value;
    if (!exact_best.empty()) {
      out["exact"] = exact_best;
      out["orientation_exact"] = exact_orientation;
    }
    out["limit"] = limit_value;
    out["limit_exact"] = symbolic::canonical_text(limit.value);
    out["ratio"] = best.value / limit_value;
    out["limit_claim"] = claim.status;
    out["limit_claim_proven"] = claim.proven;
    out["limit_claim_reason"] = claim.reason;
    out["criteria_default"] = criteria_json(before);
    out["criteria_best"] = criteria_json(after);
    if (!invariant) {
      out["starts"] = best.starts;
      out["hits"] = best.hits;
    }
    print_json(out);
    return 0;
  }
  std::printf("%s (%d faces), criterion %s\n", family.name.c_str(), normals.size(), std::string(criterion_name(c)).c_str());
  std::printf("best mounting: %s = %.10g (default mounting %.10g)%s%s\n", std::string(criterion_name(c)).c_str(),
              best.value, best.value_default, exact_value.empty() ? "" : ", exactly ", exact_value.c_str());
  std::printf("  %s: %s\n", status.c_str(), how.c_str());
  if (!exact_best.empty())
    std::printf("  at the exact mounting %s the value is exactly %s%s\n", exact_orientation.c_str(), exact_best.c_str(),
                at_limit ? "" : " (its optimality is numerical)");
  const std::string limit_text = symbolic::canonical_text(limit.value);
  char limit_number[32];
  std::snprintf(limit_number, sizeof limit_number, "%.10g", limit_value);
  std::printf("limit %s%s%s, ratio %.10g: %s, %s (%s)\n", limit_text.c_str(), limit_text == limit_number ? "" : " = ",
              limit_text == limit_number ? "" : limit_number, best.value / limit_value, claim.status.c_str(),
              claim.proven ? "proven" : "numerical", claim.reason.c_str());
  std::printf("meter axes in jig coordinates (mount the meter so that its axes point along these):\n");
  const char* axis[3] = {"x", "y", "z"};
  for (int r = 0; r < 3; ++r)
    std::printf("  %s = (%15.12f, %15.12f, %15.12f)\n", axis[r], best.orientation(r, 0), best.orientation(r, 1),
                best.orientation(r, 2));
  std::printf("  criterion        default           best\n");
  const char* names[] = {"D", "A", "E", "S", "theta_bias", "theta_scale", "theta_nonorth"};
  const double b[] = {before.D, before.A, before.E, before.S, before.theta_bias, before.theta_scale, before.theta_nonorth};
  const double a[] = {after.D, after.A, after.E, after.S, after.theta_bias, after.theta_scale, after.theta_nonorth};
  for (int i = 0; i < 7; ++i) std::printf("  %-13s %14.8g %14.8g\n", names[i], b[i], a[i]);
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_positional(app, "NAME", o->name, "the jig: " + jig_names() + " (with or without jig:)");
  add_criterion(app, o->criterion);
  add_integer(app, "--starts", o->starts, 1, 100000,
              {"starts of the search over rotations (the first is the default mounting)", "starts", "64"});
  add_seed(app, o->seed);
  add_switch(app, "--json", o->json, "print one JSON object");
  return [o] { return run(*o); };
}

const Registration reg({"jig", "jig NAME [--criterion D|A|E|S] [--starts K] [--seed S] [--json]",
                        "the best way to mount the meter in a printable jig, proven where the closed forms decide",
                        62, setup});

}  // namespace
}  // namespace scalcal::cli
