// fig11 (new): the D-optimal N = 12 and N = 18 programs drawn on the unit sphere, with the
// meter's axes. Data: fig11.csv (x, y, z of each position).
#include "experiments/reproduce/figures.hpp"
#include "experiments/reproduce/format.hpp"
#include "plots/csv_writer.hpp"
#include "plots/figure.hpp"

namespace scalcal::reproduce {

using plots::CsvWriter;

void figure_sphere(Context& ctx) {
  auto& r = ctx.report;
  r.heading(2, "fig11 (new): the D-optimal N = 12 and N = 18 programs on the sphere");
  const Entry* p12 = ctx.optimum(CriterionKind::D, 12);
  const Entry* p18 = ctx.optimum(CriterionKind::D, 18);
  if (!p12 || !p18) {
    r.missing("this figure needs the optimised N = 12 and 18 programs (rejected or not computed)");
    return;
  }
  CsvWriter csv(ctx.file("fig11.csv"), {"N", "i", "x", "y", "z"});
  for (const Entry* e : {p12, p18})
    for (int i = 0; i < e->ev.positions; ++i) {
      const Vec3& v = e->program.positions[static_cast<std::size_t>(i)];
      csv.row({std::to_string(e->ev.positions), std::to_string(i + 1), csv_num(v(0)), csv_num(v(1)),
               csv_num(v(2))});
    }
  csv.close();
  std::string body =
      "set multiplot layout 1,2 title 'D-optimal programs (scalcal): positions η on the unit sphere, meter axes X Y Z'\n"
      "set parametric\nset urange [0:2*pi]\nset vrange [-pi/2:pi/2]\nset isosamples 13,9\nset view equal xyz\n"
      "set view 62,35,1.35\nunset border\nunset tics\nset xrange [-1.3:1.3]\n"
      "set yrange [-1.3:1.3]\nset zrange [-1.3:1.3]\nunset key\n"
      "set arrow 1 from 0,0,0 to 1.3,0,0 lw 2 lc rgb 'black' front\nset arrow 2 from 0,0,0 to 0,1.3,0 lw 2 lc rgb 'black' front\n"
      "set arrow 3 from 0,0,0 to 0,0,1.3 lw 2 lc rgb 'black' front\nset label 1 'X' at 1.42,0,0 front\n"
      "set label 2 'Y' at 0,1.42,0 front\nset label 3 'Z' at 0,0,1.42 front\n";
  for (int n : {12, 18})
    body += "set title 'N = " + std::to_string(n) +
            "'\nsplot cos(u)*cos(v),sin(u)*cos(v),sin(v) with lines lc rgb '#d0d0d0', \\\n      'fig11.csv' skip 1 using "
            "($1==" + std::to_string(n) + " ? $3 : NaN):4:5 with points pt 7 ps 1.8 lc rgb '" + plots::style::optimised +
            "', \\\n      '' skip 1 using ($1==" + std::to_string(n) + " ? $3 : NaN):4:5:(sprintf('%d', $2)) with labels "
            "offset 1,1 font ',10'\n";
  body += "unset multiplot\n";
  render_figure(ctx, "fig11", "D-optimal N = 12 and 18 programs on the sphere", body, 1400, 720);
  r.figure("fig11", "fig11: D-optimal programs, N = 12 (left) and N = 18 (right), on the unit sphere");
  r.paragraph("Data: [fig11.csv](fig11.csv). The paper notes that its optimised 12- and 20-position programs reach "
              "the jigs' D without forming the symmetric figures.");
}

}  // namespace scalcal::reproduce
