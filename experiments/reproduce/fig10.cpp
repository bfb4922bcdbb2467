// fig10 (new): the optimum of each criterion (D, A, E, S) against N, with its N -> infinity limit
// (numeric/limits.hpp) and the paper's Tables 1-3 programs at N = 18. Data: fig10.csv.
#include "experiments/reproduce/figures.hpp"
#include "experiments/reproduce/format.hpp"
#include "numeric/criteria/registry.hpp"
#include "plots/csv_writer.hpp"
#include "plots/figure.hpp"

namespace scalcal::reproduce {

namespace {

// The paper's normalisation of each criterion as its axis label (N^P is N^9 under the paper's model).
std::string axis_label(CriterionKind c) {
  std::string s(criterion_summary(c));
  if (const auto p = s.find("^P"); p != std::string::npos) s.replace(p, 2, "^9");
  if (const auto p = s.find("lambda_max"); p != std::string::npos) s.replace(p, 10, "λ_{max}");
  return s;
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
  paper.row({"A", "18", csv_num(ctx.paper[0].ev.A)});
  paper.row({"E", "18", csv_num(ctx.paper[1].ev.E)});
  paper.row({"S", "18", csv_num(ctx.paper[2].ev.S)});
  csv.close();
  paper.close();
  std::string body = "set multiplot layout 2,2 title 'optimum of each normalised criterion against N (scalcal), with its "
                     "limit N → ∞'\nset grid\nset xrange [8:31]\nset xlabel 'N'\nset key top right\n";
  for (auto c : kCriteria) {
    const auto lim = criterion_limit(c);
    const std::string cn(criterion_name(c));
    body += "set title '" + cn + "-criterion'\nset ylabel '" + cn + " = " + axis_label(c) + "'\n" +
            (c == CriterionKind::D ? "set format y '%.4t·10^{%T}'\n" : "set format y '%g'\n") +
            // The E and S tables of the paper sit above the curves, where a top key would cover them.
            (c == CriterionKind::E || c == CriterionKind::S ? "set key right center\n" : "set key top right\n") +
            "plot 'fig10.csv' skip 1 using 2:(strcol(1) eq '" + cn + "' ? $3 : NaN) with linespoints pt 9 ps 1.3 lc rgb '" +
            plots::style::optimised + "' title 'scalcal optimum', \\\n     " + csv_num(lim.value) +
            " with lines lw 2 lc rgb '" + plots::style::limit + "' title " + plots::gp_quote("limit " + std::string(lim.exact)) +
            (c == CriterionKind::D ? std::string("\n")
                                   : ", \\\n     'fig10_paper.csv' skip 1 using 2:(strcol(1) eq '" + cn +
                                         "' ? $3 : NaN) with points pt 6 ps 2 lw 2 lc rgb '" + plots::style::paper +
                                         "' title 'paper, Table (N = 18)'\n");
  }
  body += "unset multiplot\n";
  render_figure(ctx, "fig10", "optimum of D, A, E, S against N with the analytic limits", body, 1300, 1000);
  r.figure("fig10", "fig10: scalcal's optimum of each criterion against N; red: the N → ∞ limit");
  r.paragraph("Data: [fig10.csv](fig10.csv) (with the multistart's starts, hits and seconds per N), "
              "[fig10_paper.csv](fig10_paper.csv).");
}

}  // namespace scalcal::reproduce
