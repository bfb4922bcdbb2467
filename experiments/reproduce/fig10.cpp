// fig10 (new): the optimum of each criterion (D, A, E, S) against N, with its N -> infinity limit
// (numeric/limits.hpp) and the paper's Tables 1-3 programs at N = 18. Data: fig10.csv.
#include <algorithm>
#include <cmath>

#include "experiments/reproduce/figures.hpp"
#include "experiments/reproduce/format.hpp"
#include "numeric/criteria/registry.hpp"
#include "plots/csv_writer.hpp"
#include "plots/figure.hpp"

namespace scalcal::reproduce {

namespace {

// The paper's normalisation of each criterion as its axis label (N^P is N^9 under the paper's model);
// the panel's own label names the criterion. D is drawn in units of 10^7, written "/ 10^7" as in Fig. 6.
std::string axis_label(CriterionKind c) {
  std::string s(criterion_summary(c));
  if (const auto p = s.find("^P"); p != std::string::npos) s.replace(p, 2, plots::sup("9"));
  if (const auto p = s.find("lambda_max"); p != std::string::npos) s.replace(p, 10, "λ" + plots::sub("max"));
  if (const auto p = s.find("max_r"); p != std::string::npos) s.replace(p, 5, "max" + plots::sub("r"));
  if (c == CriterionKind::D) s += " / 10" + plots::sup("7");
  return s;
}

// The y ticks of a panel whose values span [lo, hi]: a step of 1, 2 or 5 times a power of ten giving
// about five ticks, and every tick printed with the digits that step needs (12.00, 12.05, 12.10; not
// 12, 12.05, 12.1), one convention for all four panels.
std::string y_ticks(double lo, double hi) {
  const double raw = std::max(hi - lo, 1e-12 * std::abs(hi)) / 5;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / power;
  const double step = (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * power;
  const int digits = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
  return "set ytics " + csv_num(step) + "\nset format y '%." + std::to_string(digits) + "f'\n";
}

}  // namespace

using plots::CsvWriter;

void figure_limits(Context& ctx) {
  auto& r = ctx.report;
  r.heading(2, "fig10 (new): the optimum of each criterion against N, with its limit");
  CsvWriter csv(ctx.file("fig10.csv"), {"criterion", "N", "optimum", "limit", "starts", "hits", "seconds"});
  for (auto c : kCriteria)
    for (int n : ctx.optimised_sizes(c)) {
      const Entry& e = *ctx.optimum(c, n);
      csv.row({std::string(criterion_name(c)), std::to_string(n), csv_num(e.ev.value(c)),
               csv_num(criterion_limit(c).value), std::to_string(e.starts), std::to_string(e.hits),
               csv_num(e.seconds)});
    }
  CsvWriter paper(ctx.file("fig10_paper.csv"), {"criterion", "N", "value"});
  paper.row({"A", "18", csv_num(ctx.paper[0].ev.value(CriterionKind::A))});
  paper.row({"E", "18", csv_num(ctx.paper[1].ev.value(CriterionKind::E))});
  paper.row({"S", "18", csv_num(ctx.paper[2].ev.value(CriterionKind::S))});
  csv.close();
  paper.close();
  // Four panels on the page width, one key above them (a plot of its own, so it may use the full
  // width). Each limit is a black line drawn under the optimum's points, named in the panel.
  using namespace plots::style;
  std::string body =
      "set multiplot\nset grid\nset xrange [8:31]\nset xtics 2\n"
      "set style textbox opaque noborder margins 0.5,0.5\n";
  const char* frames[] = {"0.09\nset rmargin at screen 0.48\nset tmargin at screen 0.9\nset bmargin at screen 0.56",
                          "0.59\nset rmargin at screen 0.98\nset tmargin at screen 0.9\nset bmargin at screen 0.56",
                          "0.09\nset rmargin at screen 0.48\nset tmargin at screen 0.47\nset bmargin at screen 0.13",
                          "0.59\nset rmargin at screen 0.98\nset tmargin at screen 0.47\nset bmargin at screen 0.13"};
  for (std::size_t i = 0; i < kCriteria.size(); ++i) {
    const auto c = kCriteria[i];
    const auto lim = criterion_limit(c);
    const std::string cn(criterion_name(c));
    // D in units of 10^7, so its ticks read 1.55 rather than 1.5500·10^7.
    const std::string scale = c == CriterionKind::D ? "/1e7" : "";
    const double unit = c == CriterionKind::D ? 1e7 : 1;
    double lo = lim.value, hi = lim.value;
    for (int n : ctx.optimised_sizes(c)) {
      lo = std::min(lo, ctx.optimum(c, n)->ev.value(c));
      hi = std::max(hi, ctx.optimum(c, n)->ev.value(c));
    }
    for (std::size_t k = 0; k < 3; ++k)
      if (c == kCriteria[k + 1]) hi = std::max(hi, ctx.paper[k].ev.value(c));
    body += "set lmargin at screen " + std::string(frames[i]) + "\n" +
            (i >= 2 ? "set xlabel 'N'\n" : "unset xlabel\n") + "set ylabel " + plots::gp_quote(axis_label(c)) + "\n" +
            y_ticks(lo / unit, hi / unit) + "set label 1 '(" + "abcd"[i] + ") " + cn +
            "' at graph 0.97, graph 0.88 right front\nset label 2 " + plots::gp_quote("limit " + math_text(lim.exact)) +
            " at graph 0.97, first " + csv_num(lim.value) + scale + " offset 0,0.9 right front boxed\nplot " +
            csv_num(lim.value) + scale + " with lines lw 1.5 lc rgb '" + limit +
            "' notitle, \\\n     'fig10.csv' skip 1 using 2:(strcol(1) eq '" + cn + "' ? $3" + scale +
            " : NaN) with linespoints pt 9 ps 0.7 lw 1 lc rgb '" + optimised +
            "' notitle, \\\n     'fig10_paper.csv' "
            "skip 1 using 2:(strcol(1) eq '" +
            cn + "' ? $3 : NaN) with points pt 6 ps 1.3 lw 2 lc rgb '" + plots::style::paper + "' notitle\n";
  }
  body +=
      std::string("unset label\nunset xlabel\nunset ylabel\nunset grid\nunset border\nunset tics\n") +
      "set lmargin at screen 0.02\nset rmargin at screen 0.98\nset tmargin at screen 0.99\nset bmargin at screen 0.93\n"
      "set xrange [0:1]\nset yrange [0:1]\nset key center center horizontal maxcols 3 Left reverse samplen 2\n"
      "plot NaN with lines lw 1.5 lc rgb '" +
      limit +
      "' title 'limit N → ∞', \\\n     NaN with linespoints pt 9 "
      "ps 0.7 lw 1 lc rgb '" +
      optimised +
      "' title 'scalcal optimum', \\\n     NaN with points pt 6 ps 1.3 lw 2 "
      "lc rgb '" +
      plots::style::paper + "' title 'paper, Tables 1–3'\nunset multiplot\n";
  render_figure(ctx, "fig10", "optimum of D, A, E, S against N with the analytic limits", body, plots::kPageWidthCm, 9);
  r.figure("fig10",
           "fig10: scalcal's optimum of each criterion against N (triangles), its N → ∞ limit (line) and the "
           "paper's Tables 1-3 programs at N = 18 (circles)");
  r.paragraph(
      "Data: [fig10.csv](fig10.csv) (with the multistart's starts, hits and seconds per N), "
      "[fig10_paper.csv](fig10_paper.csv).");
}

}  // namespace scalcal::reproduce
