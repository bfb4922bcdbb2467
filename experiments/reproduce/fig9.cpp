// Fig. 9 of the paper: the error ellipse of each criterion's N = 18 program in the
// (scale-factor deviation, non-orthogonality) plane, the projection of the 9-D error ellipsoid:
// the marginal covariance N K restricted to the scale-factor parameter and the non-orthogonality
// parameter with the largest variances (those that set theta_scale and theta_nonorth).
// Data: fig9.csv (ellipse points), fig9_cov.csv (the 2x2 covariances).
#include <algorithm>
#include <cmath>

#include "experiments/reproduce/figures.hpp"
#include "experiments/reproduce/format.hpp"
#include "numeric/model/paper9.hpp"
#include "plots/csv_writer.hpp"
#include "plots/figure.hpp"

namespace scalcal::reproduce {

using plots::CsvWriter;

void figure_9(Context& ctx) {
  // Colour says the criterion (plots::style::criterion, D A E S); scalcal's optima are lines, the
  // paper's Tables 1-3 open symbols along their ellipse, so a table that nearly equals scalcal's optimum
  // (Table 1 and the A-optimal program) still shows as symbols on the line.
  struct Item {
    std::string label, key;  // label: fig9.csv's; key: the figure's
    const Entry* entry;
    std::string how;  // gnuplot style
  };
  using namespace plots::style;
  std::vector<Item> items;
  static const Entry classic = make_entry("analytic", "classic18", "ref. [14]", Program::classic18());
  items.push_back(
      {"[14] 45° (classic 18)", "[14] 45°", &classic, std::string("with lines lw 2 dt 3 lc rgb '") + grey + "'"});
  for (std::size_t i = 0; i < kCriteria.size(); ++i)
    if (const Entry* e = ctx.optimum(kCriteria[i], 18)) {
      const std::string cn(criterion_name(kCriteria[i]));
      items.push_back(
          {"scalcal " + cn + "-optimal", "scalcal " + cn, e,
           std::string("with lines lw 2 dt ") + std::to_string(criterion_dash[i]) + " lc rgb '" + criterion[i] + "'"});
    }
  const char* paper_labels[] = {"paper Table 1 (A)", "paper Table 2 (E)", "paper Table 3 (S)"};
  const char* paper_keys[] = {"paper A (Tab. 1)", "paper E (Tab. 2)", "paper S (Tab. 3)"};
  const int paper_points[] = {6, 8, 4};  // open disc, triangle, square
  for (std::size_t i = 0; i < 3; ++i)
    items.push_back({paper_labels[i], paper_keys[i], &ctx.paper[i],
                     "every 8 with points pt " + std::to_string(paper_points[i]) + " ps 0.6 lw 1.5 lc rgb '" +
                         criterion[i + 1] + "'"});

  CsvWriter pts(ctx.file("fig9.csv"), {"program", "label", "k", "scale", "nonorth"});
  CsvWriter cov(ctx.file("fig9_cov.csv"), {"program", "label", "scale_parameter", "nonorth_parameter", "var_scale",
                                           "var_nonorth", "covariance", "correlation", "area_over_pi"});
  std::string plot = "plot ";
  double extent_x = 0, extent_y = 0;  // the largest half-extents along the axes
  for (std::size_t i = 0; i < items.size(); ++i) {
    const auto& it = items[i];
    const Mat9 C = static_cast<double>(it.entry->ev.positions) * it.entry->ev.K;
    int r = 3, s = 6;
    for (int j = 3; j < 6; ++j)
      if (C(j, j) > C(r, r)) r = j;
    for (int j = 6; j < 9; ++j)
      if (C(j, j) > C(s, s)) s = j;
    const double a = C(r, r), b = C(s, s), c = C(r, s);
    extent_x = std::max(extent_x, std::sqrt(a));
    extent_y = std::max(extent_y, std::sqrt(b));
    cov.row({it.entry->name, CsvWriter::text(it.label), std::string(kParameterNames[static_cast<std::size_t>(r)]),
             std::string(kParameterNames[static_cast<std::size_t>(s)]), csv_num(a), csv_num(b), csv_num(c),
             csv_num(c / std::sqrt(a * b)), csv_num(std::sqrt(a * b - c * c))});
    // Points C^(1/2) (cos t, sin t) through the Cholesky factor: the 1-sigma ellipse x^T C^-1 x = 1.
    const double l11 = std::sqrt(a), l21 = c / l11, l22 = std::sqrt(std::max(0.0, b - l21 * l21));
    for (int k = 0; k <= 200; ++k) {
      const double t = 2 * M_PI * k / 200;
      pts.row({it.entry->name, CsvWriter::text(it.label), std::to_string(k), csv_num(l11 * std::cos(t)),
               csv_num(l21 * std::cos(t) + l22 * std::sin(t))});
    }
    // "every" comes before "using" in gnuplot's grammar.
    const auto every = it.how.rfind("every ", 0) == 0 ? it.how.substr(0, it.how.find(" with")) + " " : std::string();
    plot += (i ? ", \\\n     " : "") + std::string("'fig9.csv' skip 1 ") + every + "using (strcol(2) eq " +
            plots::gp_quote(it.label) + " ? $4 : NaN):5 " + it.how.substr(every.size()) + " title " +
            plots::gp_quote(it.key);
  }
  pts.close();
  cov.close();
  // Square axes (an ellipse keeps its shape), the key to the right where the ellipses leave room.
  const std::string body =
      "set grid\nset size ratio -1\nset xlabel 'scale factor  √N σ" + plots::sub("δk") + " / σ" + plots::sub("ω") +
      "'\nset ylabel 'non-orthogonality  √N σ" + plots::sub("γ") + " / σ" + plots::sub("ω") +
      "'\nset key outside right center Left reverse samplen 2 width -3 spacing 1.2\nset xzeroaxis\nset yzeroaxis\n"
      "set xtics 1\nset ytics 1\nset xrange [" +
      csv_num(-1.08 * extent_x) + ":" + csv_num(1.08 * extent_x) + "]\nset yrange [" + csv_num(-1.08 * extent_y) + ":" +
      csv_num(1.08 * extent_y) + "]\n" + plot + "\n";
  render_figure(ctx, "fig9", "error ellipses in the (scale factor, non-orthogonality) plane (the paper's Fig. 9)", body,
                plots::kColumnWidthCm, 6.5);
  auto& rep = ctx.report;
  rep.heading(2, "Fig. 9: error ellipses in the (scale factor, non-orthogonality) plane");
  rep.figure("fig9",
             "Fig. 9: 1-σ error ellipses of the N = 18 programs, projected on (δk, γ): scalcal's optimum for "
             "each criterion (lines), the paper's Tables 1-3 (symbols in the colour of their criterion) and "
             "the classic 18-position program [14] (dotted)");
  rep.paragraph(
      "Each ellipse is x^T C^-1 x = 1 with C the 2x2 block of N K for the scale-factor parameter and the "
      "non-orthogonality parameter of largest variance; its half-extents along the axes are θ_scale and "
      "θ_nonorth. D shrinks the area, A the sum of the variances, E the longest half-axis, S the larger "
      "of the two variances. Data: [fig9.csv](fig9.csv), covariances in [fig9_cov.csv](fig9_cov.csv).");
}

}  // namespace scalcal::reproduce
