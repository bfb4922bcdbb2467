// Fig. 8 of the paper: theta_bias, theta_scale, theta_nonorth for the N = 18 (a) and N = 9 (b)
// programs optimised by D, A, E, S and the analytic programs [12], [14], [13], ordered by
// decreasing theta_nonorth as in the paper; the paper's own Tables 1-3 programs beside scalcal's.
// Data: fig8a.csv, fig8b.csv.
#include <algorithm>

#include "experiments/reproduce/figures.hpp"
#include "experiments/reproduce/format.hpp"
#include "plots/csv_writer.hpp"
#include "plots/figure.hpp"

namespace scalcal::reproduce {

using plots::CsvWriter;

namespace {

struct Bar {
  std::string label;
  const Entry* entry;
};

// One panel of bars: theta_bias, theta_scale, theta_nonorth per program (dark, medium, light, so
// the three stay apart in greyscale), theta_nonorth's value above its bar. The program labels are
// rotated and end at their group's tick.
std::string panel(const std::string& csv, const std::string& label, std::size_t bars, double top, bool key) {
  using namespace plots::style;
  auto title = [key](const char* t) { return key ? "title " + plots::gp_quote(t) : std::string("notitle"); };
  return "set label 1 " + plots::gp_quote(label) +
         " at graph 0.5, graph 0.92 center front\nset yrange [0:" + csv_num(top) +
         "]\nset xrange [0.4:" + std::to_string(bars) + ".75]\nplot '" + csv +
         "' skip 1 using ($1-0.27):4 with boxes lc rgb '" + group[0] + "' " + title(theta_bias) +
         ", \\\n     '' skip 1 using 1:5:xtic(2) with boxes lc rgb '" + group[1] + "' " + title(theta_scale) +
         ", \\\n     '' skip 1 using ($1+0.27):6 with boxes lc rgb '" + group[2] + "' " + title(theta_nonorth) +
         ", \\\n     '' skip 1 using ($1+0.27):6:(sprintf('{/*0.9 %.2f}', $6)) with labels offset 0,0.6 notitle\n";
}

std::size_t write_panel(Context& ctx, const std::string& file, std::vector<Bar> bars, double& top) {
  top = 0;
  for (const auto& b : bars) top = std::max(top, 1.17 * b.entry->ev.theta_nonorth);
  std::stable_sort(bars.begin(), bars.end(),
                   [](const Bar& a, const Bar& b) { return a.entry->ev.theta_nonorth > b.entry->ev.theta_nonorth; });
  CsvWriter csv(ctx.file(file), {"order", "label", "program", "theta_bias", "theta_scale", "theta_nonorth"});
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const auto& v = bars[i].entry->ev;
    csv.row({std::to_string(i + 1), CsvWriter::text(bars[i].label), CsvWriter::text(bars[i].entry->name),
             csv_num(v.theta_bias), csv_num(v.theta_scale), csv_num(v.theta_nonorth)});
  }
  return bars.size();
}

}  // namespace

void figure_8(Context& ctx) {
  static const Entry rot6 = make_entry("analytic", "rotation-6", "ref. [12]", Program::rotation(6));
  static const Entry classic = make_entry("analytic", "classic18", "ref. [14]", Program::classic18());
  // Labels a reader can follow without the paper: what the analytic programs do (the caption says it
  // in full) with their reference, the criterion each optimum is for, and whose it is.
  std::vector<Bar> a = {{"60° turns [12]", &rot6}, {"45° pairs [14]", &classic}};
  std::vector<Bar> b = {{"on 3 axes [13]", &ctx.analytic9[0]}, {"on 2 axes [14]", &ctx.analytic9[1]}};
  for (auto c : kCriteria) {
    if (const Entry* e = ctx.optimum(c, 18)) a.push_back({std::string(criterion_name(c)) + "-optimal", e});
    if (const Entry* e = ctx.optimum(c, 9)) b.push_back({std::string(criterion_name(c)) + "-optimal", e});
  }
  const char* paper_labels[] = {"paper's A (Tab. 1)", "paper's E (Tab. 2)", "paper's S (Tab. 3)"};
  for (int i = 0; i < 3; ++i) a.push_back({paper_labels[i], &ctx.paper[static_cast<std::size_t>(i)]});
  double top_a = 0, top_b = 0;
  const std::size_t na = write_panel(ctx, "fig8a.csv", a, top_a), nb = write_panel(ctx, "fig8b.csv", b, top_b);
  // One y scale for both panels, so that bars of N = 18 and N = 9 compare by height.
  const double top = std::max(top_a, top_b);
  const std::string body =
      "set multiplot\nset lmargin at screen 0.17\nset rmargin at screen 0.98\nset grid ytics\n"
      "set style fill solid 1.0 border rgb 'black'\nset boxwidth 0.27\nset ylabel \"" +
      std::string(plots::style::theta_q) +
      " = √(N max K(r,r))\\nper unit σ\"\nset ytics 2\nset xtics rotate by 35 right nomirror\n"
      "set key top right Left reverse samplen 1 width -2\nset tmargin at screen 0.99\nset bmargin at screen 0.65\n" +
      panel("fig8a.csv", "(a) N = 18", na, top, true) +
      "unset key\nset tmargin at screen 0.47\nset bmargin at screen 0.13\n" +
      panel("fig8b.csv", "(b) N = 9", nb, top, false) + "unset multiplot\n";
  render_figure(ctx, "fig8", "thetas of the N = 18 and N = 9 programs by criterion (the paper's Fig. 8)", body,
                plots::kColumnWidthCm, 12);
  auto& r = ctx.report;
  r.heading(2, "Fig. 8: RMS errors by optimisation criterion, N = 18 and N = 9");
  r.figure("fig8",
           "Fig. 8: θ_bias, θ_scale, θ_nonorth per unit σ for N = 18 (a) and N = 9 (b), on one scale, by "
           "decreasing θ_nonorth: the analytic programs (\"60° turns [12]\": each pair of axes takes 6 positions "
           "60° apart turning about the third axis; \"45° pairs [14]\": each axis along and against the vector and "
           "4 positions at 45° per pair of axes; \"on 3 axes [13]\" and \"on 2 axes [14]\": the 6 axis positions "
           "and 3 where the vector projects equally on three or on two axes, the latter 9 of [14]'s 18), "
           "scalcal's optimum for each criterion D, A, E, S (\"D-optimal\" ...), and the paper's Tables 1-3 "
           "programs (\"paper's A (Tab. 1)\" ...)");
  r.paragraph(
      "Data: [fig8a.csv](fig8a.csv), [fig8b.csv](fig8b.csv). \"paper's A (Tab. 1)\" ... are the paper's own "
      "Table 1-3 programs, evaluated by scalcal from the printed angles (0.1° resolution).");
}

}  // namespace scalcal::reproduce
