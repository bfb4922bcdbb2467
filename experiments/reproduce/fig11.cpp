// fig11 (new): the D-optimal N = 12 and N = 18 programs in a tilt-azimuth view of the unit sphere,
// every position visible. Data: fig11.csv (x, y, z of each position).
#include "experiments/reproduce/figures.hpp"
#include "experiments/reproduce/format.hpp"
#include "plots/csv_writer.hpp"
#include "plots/figure.hpp"

namespace scalcal::reproduce {

using plots::CsvWriter;

namespace {

// A tilt-azimuth view of the sphere: each position at the distance of its tilt from +Z (0-180°) from the
// centre, in the direction of its azimuth from +X. Distances from the centre are true and the map only
// stretches sideways, so two positions are at least as far apart as on the sphere and every position
// shows (a perspective view of the sphere hid some behind others). Rings at 45°, 90° (the equator, dark)
// and 135° tilt; the rim is -Z.
std::string sphere_body() {
  using namespace plots::style;
  std::string body =
      "set multiplot\nunset border\nunset tics\nunset key\nset size ratio -1\nset xrange [-212:212]\n"
      "set yrange [-200:200]\nset tmargin at screen 0.9\nset bmargin at screen 0.13\n"
      "tilt(z) = acos(z > 1 ? 1 : z < -1 ? -1 : z)*180/pi\n"
      "px(x,y,z) = tilt(z)*cos(atan2(y,x))\npy(x,y,z) = tilt(z)*sin(atan2(y,x))\n";
  for (int ring = 1; ring <= 4; ++ring)
    body += "set object " + std::to_string(ring) + " circle at 0,0 size " + std::to_string(45 * ring) +
            " fs empty border lc rgb '" + (ring % 2 ? "#c8c8c8' lw 1" : std::string(grey) + "' lw 1.5") + " back\n";
  body +=
      "do for [k=0:7] { set arrow 10+k from 0,0 to 180*cos(k*pi/4),180*sin(k*pi/4) nohead lc rgb '#c8c8c8' lw 1 "
      "back }\nset label 11 '+X' at 188,0 left front\nset label 12 '+Y' at 0,194 center front\n"
      "set label 13 '−X' at -188,0 right front\nset label 14 '−Y' at 0,-196 center front\n"
      "set label 5 'centre +Z; rings: tilt from +Z of 45°, 90° (the equator, dark) and 135°; rim −Z; angle: "
      "azimuth from +X towards +Y' at screen 0.5, screen 0.03 center front\n";
  const char* frames[] = {"0.098\nset rmargin at screen 0.402", "0.598\nset rmargin at screen 0.902"};
  int panel = 0;
  for (int n : {12, 18}) {
    const std::string at = "($1==" + std::to_string(n) + " ? px($3,$4,$5) : NaN):(py($3,$4,$5))";
    body += "set lmargin at screen " + std::string(frames[panel]) + "\nset label 4 '(" + "ab"[panel] +
            ") N = " + std::to_string(n) + "' at screen " + (panel ? "0.52" : "0.02") + ", screen 0.96 left front\n" +
            "plot 'fig11.csv' skip 1 using " + at + " with points pt 7 ps 2.3 lc rgb '" + optimised +
            "', \\\n     '' skip 1 using " + at + ":(sprintf('{/*0.9 %d}', $2)) with labels tc rgb 'white'\n";
    ++panel;
  }
  return body + "unset multiplot\n";
}

}  // namespace

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
  render_figure(ctx, "fig11", "D-optimal N = 12 and 18 programs in a tilt-azimuth view", sphere_body(),
                plots::kPageWidthCm, 6.5);
  r.figure("fig11",
           "fig11: D-optimal programs (scalcal), N = 12 (a) and N = 18 (b): each position, numbered as in "
           "fig11.csv, at its tilt from the meter's +Z axis (distance from the centre: 0° at the centre, 90° "
           "on the dark ring, 180° on the rim) and its azimuth from +X towards +Y (direction), so that every "
           "position shows");
  r.paragraph(
      "Data: [fig11.csv](fig11.csv). The paper notes that its optimised 12- and 20-position programs reach "
      "the jigs' D without forming the symmetric figures.");
}

}  // namespace scalcal::reproduce
