// The programs every figure draws from, computed once per run (programs.hpp).
#include "experiments/reproduce/programs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "experiments/reproduce/format.hpp"
#include "numeric/model/design.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/program/program_names.hpp"

#include "numeric/synthesis/multistart.hpp"
#include "numeric/synthesis/random_search.hpp"

namespace scalcal::reproduce {

void compute_analytic(Context& ctx) {
  // Green squares of Fig. 4: orbits of the octahedral group with projections 1, sqrt2/2, sqrt3/3.
  for (int a = 0; a <= 8; ++a)
    for (int e = 0; e <= 4; ++e)
      for (int d = 0; d <= 6; ++d) {
        const int n = 6 * a + 12 * e + 8 * d;
        if (n < 9 || n > 48) continue;
        const std::string name = "octahedral-" + std::to_string(a) + "-" + std::to_string(e) + "-" + std::to_string(d);
        Entry en = make_entry("uniform", name, "Fig. 4 (squares)", Program::octahedral(a, e, d));
        if (en.ev.full_rank()) ctx.uniform.push_back(std::move(en));
      }
  // Stars of Fig. 4: k positions per ring about each axis (Fig. 2 is k = 6), N = 3k.
  for (int k = 3; k <= 16; ++k) {
    Entry en = make_entry("rotation", "rotation-" + std::to_string(k), k == 6 ? "Fig. 2, ref. [12]" : "Fig. 4 (stars)",
                          Program::rotation(k));
    if (en.ev.full_rank()) ctx.rotation.push_back(std::move(en));
  }
  ctx.rotation.push_back(make_entry("rotation", "rotation-4-p45", "Fig. 4 (stars)", Program::rotation(4, 45.0)));
  std::sort(ctx.rotation.begin(), ctx.rotation.end(),
            [](const Entry& x, const Entry& y) { return x.ev.positions < y.ev.positions; });
  ctx.jigs.push_back(make_entry("jig", "dodecahedral-12", "Fig. 4, ref. [25]", Program::dodecahedral()));
  ctx.jigs.push_back(make_entry("jig", "icosahedral-20", "Fig. 4, ref. [25]", Program::icosahedral()));
  // Every printable jig the registry holds (a new jig family file shows up here with no edit); the
  // cube and the octahedron, with fewer faces than parameters, cannot be drawn.
  for (const auto& names : program_names())
    if (names.group == "jig")
      for (const auto& l : names.listed) {
        Entry en = make_entry("printable", l.name, l.source, *names.resolve(l.name));
        if (en.ev.full_rank()) ctx.printable.push_back(std::move(en));
      }
  ctx.paper.push_back(make_entry("paper", "table1-A", "Table 1", *named_program("table1-A")));
  ctx.paper.push_back(make_entry("paper", "table2-E", "Table 2", *named_program("table2-E")));
  ctx.paper.push_back(make_entry("paper", "table3-S", "Table 3", *named_program("table3-S")));
  ctx.analytic9.push_back(make_entry("analytic", "nine-3axes", "ref. [13]", Program::nine_three_axes()));
  ctx.analytic9.push_back(make_entry("analytic", "nine-2axes", "refs. [8, 14]", Program::nine_two_axes()));
}

void compute_random(Context& ctx) {
  const auto t0 = std::chrono::steady_clock::now();
  // The paper's dashed line: the best of 100000 uniform random programs per N (random_search runs
  // on all cores; it is fast enough that --quick keeps the paper's count).
  ctx.random_count = 100000;
  const int n_lo = 9, n_hi = 36;
  // One part per N, weighted by N: a random program costs its N rows.
  const double all_rows = (n_lo + n_hi) * (n_hi - n_lo + 1) / 2.0;
  double rows_before = 0;
  for (int n = n_lo; n <= n_hi; ++n) {
    ctx.progress.part(rows_before / all_rows, n / all_rows, "N = " + std::to_string(n));
    rows_before += n;
    const RandomSearchResult r =
        random_search(n, ctx.random_count, CriterionKind::D, ctx.options.seed, ctx.options.threads);
    ctx.random_best.emplace(n, make_entry("random", "random-best-" + std::to_string(n), "Fig. 4 (dashed)", r.program));
  }
  ctx.timings.emplace_back("random programs",
                           std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

void compute_optimised(Context& ctx) {
  const auto t0 = std::chrono::steady_clock::now();
  // synthesize() runs its starts in worker processes (Ipopt's MUMPS is not thread-safe), on all
  // cores; the plan is sized for the 10-minute budget. starts = 0 is synthesize()'s own default
  // (meant to find the global optimum for N <= 30).
  struct Plan {
    CriterionKind criterion;
    std::vector<int> sizes;
    int starts;
  };
  std::vector<Plan> plans;
  auto range = [](int lo, int hi) {
    std::vector<int> v;
    for (int n = lo; n <= hi; ++n) v.push_back(n);
    return v;
  };
  if (ctx.options.quick) {
    plans = {{CriterionKind::D, {9, 12, 18, 20}, 4},
             {CriterionKind::A, {9, 18}, 2},
             {CriterionKind::E, {9, 18}, 2},
             {CriterionKind::S, {9, 18}, 2}};
  } else {
    plans = {{CriterionKind::D, range(9, 30), 0},
             {CriterionKind::A, range(9, 30), 0},
             {CriterionKind::E, range(9, 30), 0},
             {CriterionKind::S, range(9, 30), 0}};
  }
  // One part of the stage per (criterion, N), weighted by the seconds one N took in a full run on two
  // cores (fig10.csv's seconds column, N = 9..30: D 0.012, A 0.018, E 1.0, S 1.5 on average): E and S
  // take nearly all of the stage.
  auto weight = [](CriterionKind c) {
    if (c == CriterionKind::D) return 0.012;
    if (c == CriterionKind::A) return 0.018;
    return c == CriterionKind::E ? 1.0 : 1.5;
  };
  int total = 0, done = 0;
  double all_work = 0, work_before = 0;
  for (const auto& p : plans) {
    total += static_cast<int>(p.sizes.size());
    all_work += weight(p.criterion) * static_cast<double>(p.sizes.size());
  }
  for (const auto& plan : plans)
    for (int n : plan.sizes) {
      ctx.progress.part(work_before / all_work, weight(plan.criterion) / all_work,
                        std::string(criterion_name(plan.criterion)) + ", N = " + std::to_string(n) + " (" +
                            std::to_string(done + 1) + "/" + std::to_string(total) + ")");
      work_before += weight(plan.criterion);
      SynthesisOptions so;
      so.positions = n;
      so.criterion = plan.criterion;
      so.starts = plan.starts;
      so.seed = ctx.options.seed;
      so.threads = ctx.threads();
      so.progress = [&ctx](int d, int t) { ctx.progress.step(d, t); };
      const SynthesisResult r = synthesize(so);
      Entry e =
          make_entry("optimised", "optimised-" + std::string(criterion_name(plan.criterion)) + "-" + std::to_string(n),
                     "scalcal synthesize", r.program);
      e.starts = r.starts;
      e.hits = r.hits;
      e.seconds = r.seconds;
      // A result is kept only if scalcal's own evaluation confirms it: full rank and a positive,
      // finite criterion. Anything else is reported as a failed optimisation, never plotted.
      const double v = e.ev.value(plan.criterion);
      if (!e.ev.full_rank() || !std::isfinite(v) || v <= 0 || e.ev.raw(CriterionKind::E) <= 0) {
        ctx.optimiser_failures.push_back(std::string(criterion_name(plan.criterion)) + ", N = " + std::to_string(n) +
                                         ": synthesize() returned value " + decimal(r.value) +
                                         "; scalcal's evaluation of its program gives " +
                                         std::string(criterion_name(plan.criterion)) + " = " + decimal(v) + ", rank " +
                                         std::to_string(e.ev.rank) + ", condition " + decimal(e.ev.condition, 3));
      } else {
        ctx.optimised.emplace(std::make_pair(plan.criterion, n), std::move(e));
      }
      ++done;
    }
  ctx.timings.emplace_back("optimised programs",
                           std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

}  // namespace scalcal::reproduce
