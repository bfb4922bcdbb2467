// The top of REPORT.md: the paper's stated numbers beside scalcal's, and two closed-form checks.
#include <cmath>

#include "experiments/reproduce/figures.hpp"
#include "experiments/reproduce/format.hpp"
#include "numeric/criteria/registry.hpp"

namespace scalcal::reproduce {

void summary(Context& ctx) {
  auto& r = ctx.report;
  const double limit = criterion_limit(CriterionKind::D).value;
  r.claim("limit of N^9 det K (Fig. 6)", "1.538e7", exact_and_decimal(criterion_limit(CriterionKind::D).exact, limit),
          pct(limit, 1.538e7));
  double best = INFINITY;
  int best_n = 0;
  for (int n : ctx.optimised_sizes(CriterionKind::D))
    if (ctx.optimum(CriterionKind::D, n)->ev.value(CriterionKind::D) < best)
      best = ctx.optimum(CriterionKind::D, n)->ev.value(CriterionKind::D), best_n = n;
  if (best_n)
    r.claim("lowest optimised N^9 det K", "1.538e7", decimal(best, 10) + " (N = " + std::to_string(best_n) + ")",
            pct(best, 1.538e7));
  const Entry& dodeca = ctx.jigs[0];
  const Entry& icosa = ctx.jigs[1];
  for (const auto& [jig, n] : {std::pair<const Entry*, int>{&dodeca, 12}, {&icosa, 20}}) {
    const Entry* opt = ctx.optimum(CriterionKind::D, n);
    r.claim(jig->name + " jig N^9 det K equals the optimised N = " + std::to_string(n) + " (Fig. 6)", "equal",
            decimal(jig->ev.value(CriterionKind::D), 10) + " vs " +
                (opt ? decimal(opt->ev.value(CriterionKind::D), 10) : std::string("MISSING (no optimiser)")),
            opt ? pct(opt->ev.value(CriterionKind::D), jig->ev.value(CriterionKind::D)) : "n/a");
  }
  // Closed forms, checked independently: the classic 18 program's moments give N^9 det K =
  // 17006112 exactly, and the icosahedral jig (a spherical 4-design) gives the limit.
  const Entry* classic = nullptr;
  for (const auto& e : ctx.uniform)
    if (e.name == "octahedral-1-1-0") classic = &e;
  if (classic)
    r.claim("check: classic18 [14] N^9 det K, closed form 17006112", "(not stated)",
            decimal(classic->ev.value(CriterionKind::D), 12), pct(classic->ev.value(CriterionKind::D), 17006112.0));
  r.claim("check: icosahedral jig N^9 det K, closed form 61509375/4", "(not stated)",
          decimal(icosa.ev.value(CriterionKind::D), 12), pct(icosa.ev.value(CriterionKind::D), limit));
}

}  // namespace scalcal::reproduce
