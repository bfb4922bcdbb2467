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
      csv.row({std::to_string(e->ev.positions), std::to_string(i + 1), csv_num(v(0)), csv_num(v(1)), csv_num(v(2))});
    }
  csv.close();
  using namespace plots::style;
  // Depth cue for `set view 62,35`: depth() > 0 faces the viewer. Front positions are filled discs with
  // white numbers; back ones open grey discs drawn first, so a front disc covers a back one it overlaps
  // and the numbers of a front and a back position never print over each other.
  std::string body =
      "set multiplot\nset parametric\nset urange [0:2*pi]\nset vrange [-pi/2:pi/2]\nset isosamples 13,9\n"
      "set view equal xyz\nset view 62,35,1.7\nunset border\nunset tics\nset xrange [-1.3:1.3]\n"
      "set yrange [-1.3:1.3]\nset zrange [-1.3:1.3]\nset margins 0,0,0,0\nset size 0.5,1.15\nunset key\n"
      "set arrow 1 from 0,0,0 to 1.3,0,0 lw 2 lc rgb 'black'\nset arrow 2 from 0,0,0 to 0,1.3,0 lw 2 lc rgb 'black'\n"
      "set arrow 3 from 0,0,0 to 0,0,1.3 lw 2 lc rgb 'black'\nset label 1 'X' at 1.45,0,0 front\n"
      "set label 2 'Y' at 0,1.5,0 front\nset label 3 'Z' at 0,0,1.42 front\n"
      "rx = 62*pi/180; rz = 35*pi/180\ndepth(x,y,z) = x*sin(rz)*sin(rx) - y*cos(rz)*sin(rx) + z*cos(rx)\n";
  int panel = 0;
  for (int n : {12, 18}) {
    const std::string only = "($1==" + std::to_string(n) + " && depth($3,$4,$5) ";
    body += "set origin " + std::string(panel ? "0.5" : "0") + ",-0.12\nset label 4 '(" + "ab"[panel] +
            ") N = " + std::to_string(n) + "' at screen " + (panel ? "0.52" : "0.02") + ", screen 0.95 left front\n" +
            "splot cos(u)*cos(v),sin(u)*cos(v),sin(v) with lines lc rgb '#d9d9d9', \\\n"
            "      'fig11.csv' skip 1 using " +
            only +
            "< 0 ? $3 : NaN):4:5 with points pt 7 ps 2.3 lc rgb 'white', \\\n"
            "      '' skip 1 using " +
            only + "< 0 ? $3 : NaN):4:5 with points pt 6 ps 2.3 lw 1.5 lc rgb '" + grey +
            "', \\\n      '' skip 1 using " + only +
            "< 0 ? $3 : NaN):4:5:(sprintf('{/*0.9 %d}', $2)) with labels tc rgb '" + grey +
            "', \\\n      '' skip 1 using " + only + ">= 0 ? $3 : NaN):4:5 with points pt 7 ps 2.3 lc rgb '" +
            optimised + "', \\\n      '' skip 1 using " + only +
            ">= 0 ? $3 : NaN):4:5:(sprintf('{/*0.9 %d}', $2)) with labels tc rgb 'white'\n";
    ++panel;
  }
  body += "unset multiplot\n";
  render_figure(ctx, "fig11", "D-optimal N = 12 and 18 programs on the sphere", body, plots::kPageWidthCm, 6.5);
  r.figure("fig11",
           "fig11: D-optimal programs (scalcal), N = 12 (a) and N = 18 (b): the positions on the unit sphere, "
           "numbered as in fig11.csv, with the meter's axes X, Y, Z; filled: on the hemisphere facing the "
           "viewer, open: behind the sphere");
  r.paragraph(
      "Data: [fig11.csv](fig11.csv). The paper notes that its optimised 12- and 20-position programs reach "
      "the jigs' D without forming the symmetric figures.");
}

}  // namespace scalcal::reproduce
