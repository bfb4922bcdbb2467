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

std::string panel(const std::string& csv, const std::string& title, std::size_t bars, double top) {
  return "set title " + plots::gp_quote(title) + "\nset yrange [0:" + csv_num(top) + "]\nset xrange [0.4:" + std::to_string(bars) +
         ".6]\nplot '" + csv + "' skip 1 using ($1-0.27):4 with boxes fs solid 0.85 lc rgb '#4c72b0' title 'θ_Δ (bias)', \\\n"
         "     '' skip 1 using 1:5:xtic(2) with boxes fs solid 0.85 lc rgb '#dd8452' title 'θ_{δk} (scale factor)', \\\n"
         "     '' skip 1 using ($1+0.27):6 with boxes fs solid 0.85 lc rgb '#55a868' title 'θ_γ (non-orthogonality)', \\\n"
         "     '' skip 1 using ($1+0.27):6:(sprintf('%.2f', $6)) with labels offset 0,0.7 font ',11' notitle\n";
}

std::size_t write_panel(Context& ctx, const std::string& file, std::vector<Bar> bars, double& top) {
  top = 0;
  for (const auto& b : bars) top = std::max(top, 1.3 * b.entry->ev.theta_nonorth);
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
  std::vector<Bar> a = {{"[12] 60° turns", &rot6}, {"[14] 45°", &classic}};
  std::vector<Bar> b = {{"[13] √3/3", &ctx.analytic9[0]}, {"[14] 9 of 18", &ctx.analytic9[1]}};
  for (auto c : kCriteria) {
    if (const Entry* e = ctx.optimum(c, 18)) a.push_back({"scalcal " + std::string(criterion_name(c)), e});
    if (const Entry* e = ctx.optimum(c, 9)) b.push_back({"scalcal " + std::string(criterion_name(c)), e});
  }
  const char* paper_labels[] = {"paper Tab.1 (A)", "paper Tab.2 (E)", "paper Tab.3 (S)"};
  for (int i = 0; i < 3; ++i) a.push_back({paper_labels[i], &ctx.paper[static_cast<std::size_t>(i)]});
  double top_a = 0, top_b = 0;
  const std::size_t na = write_panel(ctx, "fig8a.csv", a, top_a), nb = write_panel(ctx, "fig8b.csv", b, top_b);
  const std::string body =
      "set multiplot layout 2,1 spacing 0,0.12\nset grid ytics\nset style fill solid 0.85 border -1\nset boxwidth 0.27\n"
      "set ylabel 'θ_q = √(N max K(r,r))'\nset xtics rotate by -20 nomirror\nset key top right\n" +
      panel("fig8a.csv", "(a) N = 18, in order of decreasing θ_γ", na, top_a) +
      panel("fig8b.csv", "(b) N = 9, in order of decreasing θ_γ", nb, top_b) + "unset multiplot\n";
  render_figure(ctx, "fig8", "thetas of the N = 18 and N = 9 programs by criterion (the paper's Fig. 8)", body, 1200, 1200);
  auto& r = ctx.report;
  r.heading(2, "Fig. 8: RMS errors by optimisation criterion, N = 18 and N = 9");
  r.figure("fig8", "Fig. 8: θ_bias, θ_scale, θ_nonorth for N = 18 (a) and N = 9 (b), by decreasing θ_nonorth");
  r.paragraph("Data: [fig8a.csv](fig8a.csv), [fig8b.csv](fig8b.csv). \"paper Tab.k\" are the paper's own Table 1-3 "
              "programs, evaluated by scalcal from the printed angles (0.1° resolution).");
}

}  // namespace scalcal::reproduce
