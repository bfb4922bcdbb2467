// Figs. 4-6 of the paper: the generalized variance det K against N for the program classes (4),
// the same normalised by N^9 (5), and its lower part with the analytic limit 61509375/4 and the
// N whose optimum misses it (6). Data: fig4_programs.csv, fig4_random.csv.
#include <algorithm>
#include <cmath>

#include "experiments/reproduce/figures.hpp"
#include "experiments/reproduce/format.hpp"
#include "numeric/criteria/registry.hpp"
#include "plots/csv_writer.hpp"
#include "plots/figure.hpp"

namespace scalcal::reproduce {

using plots::CsvWriter;

namespace {
// Relative distance above which an optimum counts as missing the limit.
constexpr double kLimitTolerance = 1e-5;
}  // namespace

void figures_4_5_6(Context& ctx) {
  const double limit = criterion_limit(CriterionKind::D).value;
  std::vector<const Entry*> drawn;
  for (const auto* group : {&ctx.uniform, &ctx.rotation, &ctx.jigs})
    for (const auto& e : *group) drawn.push_back(&e);
  for (int n : ctx.optimised_sizes(CriterionKind::D)) drawn.push_back(ctx.optimum(CriterionKind::D, n));
  {
    auto header = entry_header();
    header.push_back("misses_limit");
    CsvWriter csv(ctx.file("fig4_programs.csv"), header);
    for (const auto* e : drawn) {
      auto cells = entry_cells(*e);
      cells.push_back(e->family == "optimised" ? (e->ev.D > limit * (1 + kLimitTolerance) ? "1" : "0") : "");
      csv.row(cells);
    }
  }
  {
    CsvWriter csv(ctx.file("fig4_random.csv"), {"N", "count", "seed", "det_K", "D"});
    for (const auto& [n, e] : ctx.random_best)
      csv.row({std::to_string(n), std::to_string(ctx.random_count), std::to_string(ctx.options.seed),
               csv_num(e.ev.det_K), csv_num(e.ev.D)});
  }
  const std::string common =
      "set grid\nset xlabel 'number of measurement positions N'\nset xrange [8:49]\nset xtics 4\nset mxtics 4\n";
  render_figure(ctx, "fig4", "generalized variance det K against N (the paper's Fig. 4)",
                common +
                    "set logscale y\nset format y '10^{%L}'\nset ylabel 'det K   (K in units of σ_ω^2)'\n"
                    "set key top right box opaque\n" +
                    class_plot(5, ctx, false));
  render_figure(ctx, "fig5", "N^9 det K against N (the paper's Fig. 5)",
                common +
                    "set logscale y\nset ylabel 'N^9 det K'\nset format y '10^{%L}'\nset key top right box opaque\n"
                    "LIMIT = " + csv_num(limit) + "\n" + class_plot(6, ctx, true));

  // Fig. 6: the lower part, linear, with the N whose optimum misses the limit circled.
  double top = 2.4e7;
  for (int n : ctx.optimised_sizes(CriterionKind::D)) top = std::max(top, 1.05 * ctx.optimum(CriterionKind::D, n)->ev.D);
  top = std::min(top, 3.2e7);
  std::string body = common + "set ylabel 'N^9 det K'\nset format y '%.2t·10^{%T}'\nset yrange [1.45e7:" +
                     csv_num(top) + "]\nset key outside below center horizontal maxcols 2 box spacing 1.1\nLIMIT = " + csv_num(limit) + "\n";
  body += "set label 1 'limit 61509375/4' at 45, LIMIT offset 0,-0.9 right tc rgb '" + std::string(plots::style::limit) +
          "'\n";
  std::string plot = class_plot(6, ctx, true);
  plot.pop_back();
  plot += ", \\\n     'fig4_programs.csv' skip 1 using 4:(strcol(13) eq '1' ? $6 : NaN) with points pt 6 ps 3.2 lw 2 "
          "lc rgb '" + std::string(plots::style::limit) + "' title 'optimum misses the limit', \\\n"
          "     '' skip 1 using 4:(strcol(13) eq '1' ? $6 : NaN):(sprintf('%d', $4)) with labels offset 0,1.6 notitle\n";
  render_figure(ctx, "fig6", "lower part of N^9 det K with the analytic limit (the paper's Fig. 6)", body + plot, 1200,
                900);

  auto& r = ctx.report;
  r.heading(2, "Figs. 4-6: generalized variance");
  r.figure("fig4", "Fig. 4: det K against N for each class of programs");
  r.figure("fig5", "Fig. 5: det K normalised by N^9");
  r.figure("fig6", "Fig. 6: lower part of N^9 det K, with the analytic limit 61509375/4");
  r.paragraph("Data: [fig4_programs.csv](fig4_programs.csv) (every program drawn, with all criteria) and "
              "[fig4_random.csv](fig4_random.csv) (the best of " + std::to_string(ctx.random_count) +
              " programs uniform on the sphere per N; `scalcal random --positions N --count " +
              std::to_string(ctx.random_count) + " --seed " + std::to_string(ctx.options.seed) + "` regenerates each).");
  std::vector<std::vector<std::string>> rows;
  std::string missed;
  for (int n : ctx.optimised_sizes(CriterionKind::D)) {
    const Entry& e = *ctx.optimum(CriterionKind::D, n);
    const bool misses = e.ev.D > limit * (1 + kLimitTolerance);
    if (misses) missed += (missed.empty() ? "" : ", ") + std::to_string(n);
    rows.push_back({std::to_string(n), decimal(e.ev.D, 8), decimal(e.ev.D / limit - 1, 3), misses ? "misses" : "reaches",
                    std::to_string(e.hits) + "/" + std::to_string(e.starts), decimal(e.seconds, 3)});
  }
  r.paragraph("The optimised D-criterion programs (scalcal's multistart; `hits` = starts that reached the best value):");
  r.table({"N", "N^9 det K", "relative excess over the limit", "limit", "hits/starts", "seconds"}, rows);
  // Compare on the N this run optimised only.
  std::string expected;
  for (int n : ctx.optimised_sizes(CriterionKind::D))
    if (n == 9 || n == 10 || n == 11 || n == 13 || n == 15) expected += (expected.empty() ? "" : ", ") + std::to_string(n);
  const auto sizes = ctx.optimised_sizes(CriterionKind::D);
  r.claim("N whose optimum misses the limit (Fig. 6)", "9, 10, 11, 13, 15",
          (missed.empty() ? std::string("none") : missed) + " (of N = " + std::to_string(sizes.front()) + ".." +
              std::to_string(sizes.back()) + " optimised here, " + std::to_string(sizes.size()) + " sizes)",
          missed == expected ? "same on these N" : "differs: paper's set on these N is {" + expected + "}");
}

}  // namespace scalcal::reproduce
