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

// The one test of a miss, for the CSV's mark, the report's table and Fig. 6's numbered circles.
bool misses_limit(const Entry& e, double limit) { return e.ev.value(CriterionKind::D) > limit * (1 + kLimitTolerance); }

// fig4_programs.csv (every program drawn, with the optimised ones that miss the limit marked) and
// fig4_random.csv (the best random program per N), which Figs. 4-6 plot.
void write_fig4_data(Context& ctx, const std::vector<const Entry*>& drawn, double limit) {
  {
    auto header = entry_header();
    header.push_back("misses_limit");
    CsvWriter csv(ctx.file("fig4_programs.csv"), header);
    for (const auto* e : drawn) {
      auto cells = entry_cells(*e);
      cells.push_back(e->family == "optimised" ? (misses_limit(*e, limit) ? "1" : "0") : "");
      csv.row(cells);
    }
  }
  {
    CsvWriter csv(ctx.file("fig4_random.csv"), {"N", "count", "seed", "det_K", "D"});
    for (const auto& [n, e] : ctx.random_best)
      csv.row({std::to_string(n), std::to_string(ctx.random_count), std::to_string(ctx.options.seed),
               csv_num(e.ev.raw(CriterionKind::D)), csv_num(e.ev.value(CriterionKind::D))});
  }
}

// The report's section on Figs. 4-6: captions, the data files, the table of optimised programs and
// the claim about which N miss the limit.
void report_figures_4_5_6(Context& ctx, double limit) {
  auto& r = ctx.report;
  r.heading(2, "Figs. 4-6: generalized variance");
  const std::string random_n = ctx.random_best.empty()
                                   ? std::string("")
                                   : " (run for N = " + std::to_string(ctx.random_best.begin()->first) + " to " +
                                         std::to_string(ctx.random_best.rbegin()->first) + " only)";
  r.figure("fig4",
           "Fig. 4: det K (K for unit-vector rows, dimensionless) against N: uniform projections (squares), "
           "rotation about each axis [12] (stars), scalcal's D-optimal programs (triangles), the dodecahedral "
           "and icosahedral jigs (open circle, diamond), the " +
               std::to_string(ctx.printable.size()) +
               " printable jigs of full rank in their default mounting (open squares; experiments/docs/jigs.md) "
               "and the best of " +
               std::to_string(ctx.random_count) + " random programs per N (dashed" + random_n + ")");
  r.figure("fig5",
           "Fig. 5: det K normalised by N^9, symbols as in Fig. 4 (key above the plot); the arrow marks the one "
           "program above the range, with its value");
  r.figure("fig6",
           "Fig. 6: lower part of N^9 det K, symbols as in Fig. 4, with the analytic limit 61509375/4; circled "
           "and numbered: the N whose optimum misses the limit");
  r.paragraph(
      "Data: [fig4_programs.csv](fig4_programs.csv) (every program drawn, with all criteria) and "
      "[fig4_random.csv](fig4_random.csv) (the best of " +
      std::to_string(ctx.random_count) +
      " programs uniform on the sphere per N; `scalcal random --positions N --count " +
      std::to_string(ctx.random_count) + " --seed " + std::to_string(ctx.options.seed) + "` regenerates each).");
  std::vector<std::vector<std::string>> rows;
  std::string missed;
  for (int n : ctx.optimised_sizes(CriterionKind::D)) {
    const Entry& e = *ctx.optimum(CriterionKind::D, n);
    const bool misses = misses_limit(e, limit);
    if (misses) missed += (missed.empty() ? "" : ", ") + std::to_string(n);
    rows.push_back({std::to_string(n), decimal(e.ev.value(CriterionKind::D), 8),
                    excess_text(e.ev.value(CriterionKind::D) / limit - 1), misses ? "misses" : "reaches",
                    std::to_string(e.hits) + "/" + std::to_string(e.starts), seconds_text(e.seconds)});
  }
  r.paragraph(
      "The optimised D-criterion programs (scalcal's multistart; `hits` = starts that reached the best value):");
  r.table({"N", "N^9 det K", "relative excess over the limit", "limit", "hits/starts", "seconds"}, rows);
  // Compare on the N this run optimised only.
  std::string expected;
  for (int n : ctx.optimised_sizes(CriterionKind::D))
    if (n == 9 || n == 10 || n == 11 || n == 13 || n == 15)
      expected += (expected.empty() ? "" : ", ") + std::to_string(n);
  const auto sizes = ctx.optimised_sizes(CriterionKind::D);
  r.claim("N whose optimum misses the limit (Fig. 6)", "9, 10, 11, 13, 15",
          (missed.empty() ? std::string("none") : missed) + " (of N = " + std::to_string(sizes.front()) + ".." +
              std::to_string(sizes.back()) + " optimised here, " + std::to_string(sizes.size()) + " sizes)",
          missed == expected ? "same on these N" : "differs: paper's set on these N is {" + expected + "}");
}

// Fig. 6's numbers of the N whose optimum misses the limit (circled). Near the limit the circles
// crowd (N = 10, 11, 13, 15 within 5 %), so their numbers stand in two alternating rows above the
// cluster, each joined to its circle by a thin line; a miss far above the limit (N = 9) is numbered
// just above its circle.
std::string miss_labels(Context& ctx, double limit) {
  using namespace plots::style;
  std::string out;
  int crowded = 0;
  int tag = 10;
  for (int n : ctx.optimised_sizes(CriterionKind::D)) {
    const Entry& e = *ctx.optimum(CriterionKind::D, n);
    if (!misses_limit(e, limit)) continue;
    const double d = e.ev.value(CriterionKind::D);
    const std::string label =
        "set label " + std::to_string(tag) + " '" + std::to_string(n) + "' at " + std::to_string(n) + ", ";
    if (d > 1.7e7) {
      out += label + csv_num(d) + " offset 0,1.1 center front tc rgb '" + medium + "'\n";
    } else {
      const double row = 1.74e7 + (crowded++ % 2) * 0.1e7;
      out += label + csv_num(row) + " center front tc rgb '" + medium + "'\n";
      out += "set arrow " + std::to_string(tag + 20) + " from " + std::to_string(n) + ", " + csv_num(d + 0.05e7) +
             " to " + std::to_string(n) + ", " + csv_num(row - 0.04e7) + " nohead lw 1 lc rgb '" + medium + "'\n";
    }
    ++tag;
  }
  return out;
}

}  // namespace

void figures_4_5_6(Context& ctx) {
  const double limit = criterion_limit(CriterionKind::D).value;
  std::vector<const Entry*> drawn;
  for (const auto* group : {&ctx.uniform, &ctx.rotation, &ctx.jigs, &ctx.printable})
    for (const auto& e : *group) drawn.push_back(&e);
  for (int n : ctx.optimised_sizes(CriterionKind::D)) drawn.push_back(ctx.optimum(CriterionKind::D, n));
  write_fig4_data(ctx, drawn, limit);
  const std::string common =
      "set grid\nset xlabel 'number of measurement positions N'\nset xrange [8:49]\nset xtics 4\nset mxtics 4\n";
  using namespace plots::style;
  // Fig. 4: the key sits top right, in the empty corner above the falling cloud of points; the range
  // ends just above the highest program (rotation at N = 9, det K = 3.3), not above the key.
  render_figure(ctx, "fig4", "generalized variance det K against N (the paper's Fig. 4)",
                common + "set logscale y\nset format y '10" + plots::sup("%L") +
                    "'\nset yrange [5e-9:2e1]\nset ylabel 'det K (dimensionless)'\n"
                    "set key top right Left reverse box opaque samplen 2.5 width -5\n" +
                    class_plot({5, true, true, false}, ctx),
                plots::kColumnWidthCm, 7);

  // Figs. 5 and 6 share Fig. 4's symbols; their lines are labelled in the plot, where a key of seven
  // entries would cover the points at one column's width. Fig. 5 has its own key of the six symbols,
  // in three rows above the frame (as Fig. 7's), so that it reads without Fig. 4.
  // The limit's label below its line, without a box: the ranges leave it room above the frame, which
  // an opaque box used to erase from N = 31 to 47.
  const std::string limit_label =
      "LIMIT = " + csv_num(limit) + "\nset label 1 'limit 61509375/4' at 47.5, LIMIT offset 0,-0.75 right front\n";
  std::vector<double> values;  // every D drawn, for the axis range
  for (const auto* e : drawn) values.push_back(e->ev.value(CriterionKind::D));
  std::sort(values.begin(), values.end());
  const auto first_random = ctx.random_best.empty() ? nullptr : &*ctx.random_best.begin();

  // Fig. 5, log scale: the range holds the bulk of the programs; a single program more than 1.5 times
  // above all others (the rotation program at N = 9) gets an arrow with its value at the top edge.
  const bool outlier = values.size() > 1 && values.back() > 1.5 * values[values.size() - 2];
  const double top5 = 1.2 * (outlier ? values[values.size() - 2] : values.back());
  std::string body5 = common + "set logscale y\nset ylabel 'N" + plots::sup("9") + " det K'\nset format y '%.1t·10" +
                      plots::sup("%T") +
                      "'\nset ytics (1.5e7, 2e7, 3e7, 5e7, 7e7, 1e8, 1.5e8, 2e8, 3e8, 5e8)\n"
                      "set yrange [1.2e7:" +
                      csv_num(top5) +
                      "]\nset tmargin at screen 0.84\nset key at screen 0.55, screen 0.995 center top horizontal "
                      "maxcols 3 Left reverse samplen 1 width -3\n" +
                      limit_label;
  // "best of 10^5 random\n(N ≤ 36)": the random line's label, in two lines.
  auto two_lines = [](std::string label) {
    if (const auto space = label.find(" ("); space != std::string::npos) label.replace(space, 1, "\\n");
    return label;
  };
  if (first_random && first_random->second.ev.value(CriterionKind::D) < top5)
    body5 += "set label 2 \"" + two_lines(random_title(ctx)) + "\" at " + std::to_string(first_random->first + 1.5) +
             ", " + csv_num(1.6 * first_random->second.ev.value(CriterionKind::D)) + " left front tc rgb '" + random +
             "'\nset arrow 2 from " + std::to_string(first_random->first + 1.8) + ", " +
             csv_num(1.3 * first_random->second.ev.value(CriterionKind::D)) + " to " +
             std::to_string(first_random->first + 0.3) + ", " +
             csv_num(1.05 * first_random->second.ev.value(CriterionKind::D)) + " size screen 0.012,20 lw 1 lc rgb '" +
             random + "'\n";
  if (outlier)
    for (const auto* e : drawn)
      if (e->ev.value(CriterionKind::D) == values.back())
        body5 += "set arrow 1 from " + std::to_string(e->ev.positions) + ", graph 0.88 to " +
                 std::to_string(e->ev.positions) + ", graph 0.99 filled size screen 0.015,20 lw 2 lc rgb '" +
                 (e->family == "rotation" ? rotation : black) + "'\nset label 3 " +
                 plots::gp_quote(gp_power(e->ev.value(CriterionKind::D))) + " at " + std::to_string(e->ev.positions) +
                 ", graph 0.93 offset 0.7,0 left front tc rgb '" + (e->family == "rotation" ? rotation : black) + "'\n";
  render_figure(ctx, "fig5", "N^9 det K against N (the paper's Fig. 5)",
                body5 + class_plot({6, true, true, true, true, false}, ctx), plots::kColumnWidthCm, 7.6);

  // Fig. 6: the lower part, linear, up to where the rotation programs (2.58e7) and the random line
  // from N = 12 on fit with room for the label above them; the random line's start above the frame is
  // stated in its label. The N whose optimum misses the limit are circled and numbered.
  const double top6 = 3.2e7;
  std::string random_label = random_title(ctx);
  double random_top = 0;
  int random_top_n = 0;
  for (const auto& [n, e] : ctx.random_best)
    if (e.ev.value(CriterionKind::D) > random_top) random_top = e.ev.value(CriterionKind::D), random_top_n = n;
  if (random_top > top6) {
    random_label.pop_back();  // "(N ≤ 36; 5.4·10^7 at N = 9)"
    random_label += "; " + gp_power(random_top, 2) + " at N = " + std::to_string(random_top_n) + ")";
  }
  random_label = two_lines(random_label);
  std::string body6 = common + "set ylabel 'N" + plots::sup("9") + " det K / 10" + plots::sup("7") +
                      "'\nset format y '%.1t'\nset yrange [1.38e7:" + csv_num(top6) + "]\nset ytics 2e6\nunset key\n" +
                      limit_label + "set label 2 \"" + random_label + "\" at 15.5, " + csv_num(0.947 * top6) +
                      " left front tc rgb '" + random + "'\n";
  body6 += miss_labels(ctx, limit);
  std::string plot = class_plot({6, false, true, true}, ctx);
  plot.pop_back();
  plot +=
      ", \\\n     'fig4_programs.csv' skip 1 using 4:(strcol(13) eq '1' ? $6 : NaN) with points pt 6 ps 1.5 lw 2 "
      "lc rgb '" +
      std::string(medium) + "' notitle\n";
  render_figure(ctx, "fig6", "lower part of N^9 det K with the analytic limit (the paper's Fig. 6)", body6 + plot,
                plots::kColumnWidthCm, 6.5);

  report_figures_4_5_6(ctx, limit);
}

}  // namespace scalcal::reproduce
