// `scalcal plot` (plot.hpp): the data and the gnuplot body of a program's figure.
#include "commands/bench/plot.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

#include "commands/core/common_options.hpp"
#include "commands/core/region_request.hpp"
#include "commands/core/usage_error.hpp"
#include "commands/core/work_bound.hpp"
#include "numeric/io/csv_table.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/region/region.hpp"

namespace scalcal::commands {
namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr int kPixels = 241;  // of the shaded region across a disk (its edge is drawn as a line too)

// Paul Tol's colours (plots/figure.hpp, style): positions dark blue, the run's path red, region grey.
constexpr const char* kPositions = "#004488";
constexpr const char* kPath = "#BB5566";
constexpr const char* kRegion = "#dddddd";
constexpr const char* kGrid = "#bbbbbb";
constexpr const char* kEdge = "#777777";

std::string num(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.6g", v);
  return s;
}

// A disk's point of a position: (x, y) / sqrt(1 + |z|) (plot.hpp); hemisphere 0 for z >= 0.
struct DiskPoint {
  int hemisphere;
  double X, Y;
};
DiskPoint on_disk(const Vec3& x) {
  const double s = 1 / std::sqrt(1 + std::abs(x.z()));
  return {x.z() >= 0 ? 0 : 1, x.x() * s, x.y() * s};
}
Vec3 from_disk(int hemisphere, double X, double Y) {
  const double r2 = X * X + Y * Y, s = std::sqrt(std::max(0.0, 2 - r2));
  return Vec3(X * s, Y * s, hemisphere == 0 ? 1 - r2 : r2 - 1);
}

// One cap of at most 90 degrees: drawn as tilt and azimuth about its axis.
const Zone* single_cap(const Region& r) {
  if (r.zones.size() != 1 || !r.candidates.empty() || r.is_sphere()) return nullptr;
  const Zone& z = r.zones.front();
  return z.min_tilt_deg == 0 && z.max_tilt_deg <= 90 ? &z : nullptr;
}

// The plane point of a position in a view: a disk's, or (tilt cos a, tilt sin a) in degrees about a cap.
struct Placed {
  int panel;
  double X, Y;
};
Placed place(const Vec3& x, const Zone* cap) {
  if (!cap) {
    const DiskPoint d = on_disk(x);
    return {d.hemisphere, d.X, d.Y};
  }
  const double t = cap->tilt_deg(x), a = azimuth_deg(*cap, x) * kDeg;
  return {0, t * std::cos(a), t * std::sin(a)};
}

std::string positions_csv(const PlotRequest& q, const Zone* cap) {
  std::string s = "panel,X,Y,label\n";
  for (std::size_t i = 0; i < q.program.positions.size(); ++i) {
    const Placed p = place(q.program.positions[i], cap);
    s += std::to_string(p.panel) + "," + num(p.X) + "," + num(p.Y) + "," + std::to_string(q.labels[i]) + "\n";
  }
  return s;
}

// The run's path, step by step in order, broken (a blank line) where it changes panel. Positions
// are joined by the great circle between them, sampled every 2 degrees.
std::string path_csv(const PlotRequest& q, const Zone* cap) {
  std::vector<std::size_t> order(q.program.positions.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return q.labels[a] < q.labels[b]; });
  std::string s = "panel,X,Y\n";
  int last = -1;
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Vec3 &a = q.program.positions[order[k - 1]], &b = q.program.positions[order[k]];
    const double angle = std::atan2(a.cross(b).norm(), a.dot(b));
    const int n = std::max(1, static_cast<int>(std::ceil(angle / (2 * kDeg))));
    for (int j = 0; j <= n; ++j) {
      const double f = static_cast<double>(j) / n;
      const Vec3 x =
          angle < 1e-12 ? a : Vec3((std::sin((1 - f) * angle) * a + std::sin(f * angle) * b) / std::sin(angle));
      const Placed p = place(x, cap);
      if (last >= 0 && p.panel != last) s += "\n";
      last = p.panel;
      s += std::to_string(p.panel) + "," + num(p.X) + "," + num(p.Y) + "\n";
    }
    s += "\n";
    last = -1;
  }
  return s;
}

// The region as pixels (1 inside, 0 outside) over a disk, for `with image`.
std::string region_csv(const Region& region, int panel) {
  std::string s = "X,Y,inside\n";
  for (int i = 0; i < kPixels; ++i) {
    for (int j = 0; j < kPixels; ++j) {
      const double X = 2.0 * j / (kPixels - 1) - 1, Y = 2.0 * i / (kPixels - 1) - 1;
      const bool inside = X * X + Y * Y <= 1 && region.contains(from_disk(panel, X, Y), 0.0);
      s += num(X) + "," + num(Y) + "," + (inside ? "1" : "0") + "\n";
    }
    s += "\n";
  }
  return s;
}

// The edges of the region's zones (circles of constant tilt about each axis) on the disks, broken
// where they change hemisphere; candidates are drawn as open circles.
std::string edges_csv(const Region& region) {
  std::string s = "panel,X,Y\n";
  for (const Zone& z : region.zones) {
    for (const double t : {z.min_tilt_deg, z.max_tilt_deg}) {
      if (t <= 0 || t >= 180) continue;
      int last = -1;
      for (int j = 0; j <= 360; ++j) {
        const DiskPoint d = on_disk(zone_position(z, t, j));
        if (last >= 0 && d.hemisphere != last) s += "\n";
        last = d.hemisphere;
        s += std::to_string(d.hemisphere) + "," + num(d.X) + "," + num(d.Y) + "\n";
      }
      s += "\n";
    }
  }
  return s;
}

// Circles of tilt every 30 degrees and the equator (disks), or every 10 degrees (a cap); meridians
// every 45 degrees.
std::string grid_csv(const Zone* cap) {
  std::string s = "X,Y\n";
  const auto polyline = [&](auto point, int n) {
    for (int j = 0; j <= n; ++j) {
      const auto [X, Y] = point(static_cast<double>(j) / n);
      s += num(X) + "," + num(Y) + "\n";
    }
    s += "\n";
  };
  const double outer = cap ? cap->max_tilt_deg : 1;
  std::vector<double> rings;
  if (cap)
    for (double t = 10; t < cap->max_tilt_deg; t += 10) rings.push_back(t);
  else
    for (double t : {30.0, 60.0, 90.0}) rings.push_back(std::sqrt(1 - std::cos(t * kDeg)));
  for (double r : rings)
    polyline(
        [r](double f) {
          return std::pair(r * std::cos(2 * std::numbers::pi * f), r * std::sin(2 * std::numbers::pi * f));
        },
        120);
  for (int m = 0; m < 8; ++m) {
    const double a = m * 45 * kDeg;
    polyline([a, outer](double f) { return std::pair(f * outer * std::cos(a), f * outer * std::sin(a)); }, 1);
  }
  return s;
}

// One panel's plot command: region pixels and edges (disks), grid, path, positions, their numbers.
// The data files are the variables the script sets (PlotData).
std::string panel_plot(int panel, bool shaded, bool disks, bool path) {
  const std::string p = std::to_string(panel);
  std::string s = "plot ";
  if (shaded && disks) s += "region" + p + "_file skip 1 using 1:2:3 with image, \\\n     ";
  s += "grid_file skip 1 using 1:2 with lines lw 0.5 lc rgb '" + std::string(kGrid) + "'";
  if (shaded && disks)
    s += ", \\\n     edges_file skip 1 using ($1==" + p + "?$2:NaN):3 with lines lw 1 lc rgb '" + kEdge + "'";
  if (path) s += ", \\\n     path_file skip 1 using ($1==" + p + "?$2:NaN):3 with lines lw 1 lc rgb '" + kPath + "'";
  s += ", \\\n     positions_file skip 1 using ($1==" + p + "?$2:NaN):3 with points pt 7 ps 0.8 lc rgb '" + kPositions +
       "', \\\n     '' skip 1 using ($1==" + p +
       "?$2:NaN):3:(sprintf('%d', $4)) with labels offset 0.9,0.6 font ',7' tc rgb '" + kPositions + "'\n";
  return s;
}

std::string figure_stem(const std::string& out, std::string& folder) {
  const std::filesystem::path p(out);
  const std::string ext = p.extension().string();
  if (ext != ".pdf" && ext != ".png" && ext != ".svg")
    throw UsageError(words("{out} ") + display_name(out) +
                     ": the figure is FILE.pdf, FILE.png or FILE.svg (all three are made, with FILE.gp)");
  folder = p.parent_path().empty() ? "." : p.parent_path().string();
  return p.stem().string();
}

std::string default_out(const std::string& program) {
  std::string stem = std::filesystem::path(program).stem().string();
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
  return (stem.empty() ? std::string("plot") : stem) + ".pdf";
}

}  // namespace

// PROGRAM is optional: --log draws a log instead.
Option optional_program() {
  Option o =
      program_argument(words("a catalogue name or a CSV file (a plan file from `plan {out}`: numbered by step, its "
                             "path drawn)"));
  o.kind = OptionKind::text;
  return o;
}

const CommandTable& plot_table() {
  // Several files are made: standard output cannot take them.
  Option figure = out_option(
      "the figure: FILE.pdf, .png or .svg (all three are made, with the gnuplot script FILE.gp and its CSV data "
      "beside them)");
  figure.writes_file = false;
  figure.unit = "file path";
  static const CommandTable table{
      "plot",
      "a picture of a program: its positions on the sphere (numbered in run order for a plan file), the region shaded",
      58,
      {optional_program(), region_option(),
       text_option("--log", "FILE", "instead of a program: a raw log (t,ix,iy,iz CSV or text t ix iy iz)", "file path"),
       text_option("--calibration", "CAL.json", words("with {log}: the calibration of that log (calibrate {out})"),
                   "file path"),
       figure}};
  return table;
}

PlotRequest plot_request(const Values& v) {
  PlotRequest q;
  if (v.given("--log") || v.given("--calibration")) {
    if (!v.given("--log") || !v.given("--calibration"))
      throw UsageError(words("{log FILE} and {calibration CAL.json} go together"));
    if (v.given("PROGRAM") || v.program || v.given("--region"))
      throw UsageError(words("{log} draws a log: it takes no PROGRAM or {region}"));
    q.log = v.text("--log");
    q.calibration = v.text("--calibration");
    q.out = v.given("--out") ? v.text("--out") : default_out(q.log);
    return q;
  }
  if (!v.given("PROGRAM") && !v.program)
    throw UsageError(words("PROGRAM is required (or {log FILE} {calibration CAL.json})"));
  q.name = v.text("PROGRAM");
  q.program = program_of(v);
  q.out = v.given("--out") ? v.text("--out") : default_out(q.name);
  q.regions = v.program ? v.list("--region") : regions_for(v.list("--region"), q.name, q.warnings);
  for (int i = 0; i < q.program.size(); ++i) q.labels.push_back(i + 1);
  std::error_code ec;
  if (!v.program && !named_program(q.name) && std::filesystem::is_regular_file(q.name, ec)) {
    const CsvTable t = read_csv(q.name);
    if (const int step = t.column("step"); step >= 0) {
      for (std::size_t i = 0; i < t.rows.size(); ++i)
        q.labels[i] = static_cast<int>(std::lround(t.rows[i].values[static_cast<std::size_t>(step)]));
      q.run_order = true;
    }
  }
  return q;
}

namespace {

// The program's figure, or the log's.
PlotResult draw(const PlotRequest& q) {
  PlotResult r;
  r.warnings = q.warnings;
  r.stem = figure_stem(q.out, r.folder);
  if (!q.log.empty()) {
    plot_log(q, r);
    return r;
  }
  const bool shaded = !is_sphere(q.regions);
  const Region region = resolve_region(q.regions, r.warnings);
  const Zone* cap = shaded ? single_cap(region) : nullptr;
  check_work(std::to_string(q.program.size()) + " positions on " + region.text(),
             plot_work(q.program.size(), static_cast<int>(region.zones.size()),
                       static_cast<int>(region.candidates.size()), shaded && !cap),
             "draw fewer positions or a region of fewer candidates");
  r.view = cap ? "cap" : "hemispheres";
  r.comment = "the positions of " + display_name(q.name) + (q.run_order ? " numbered in run order" : "") +
              (shaded ? " on the region " + region.text() : "");
  r.data.push_back({"positions_file", r.stem + "_positions.csv", positions_csv(q, cap)});
  r.data.push_back({"grid_file", r.stem + "_grid.csv", grid_csv(cap)});
  if (q.run_order) r.data.push_back({"path_file", r.stem + "_path.csv", path_csv(q, cap)});
  if (shaded && !cap) {
    for (int p = 0; p < 2; ++p) {
      const std::string n = std::to_string(p);
      r.data.push_back({"region" + n + "_file", r.stem + "_region" + n + ".csv", region_csv(region, p)});
    }
    r.data.push_back({"edges_file", r.stem + "_edges.csv", edges_csv(region)});
  }
  std::string body =
      "set size ratio -1\nunset border\nunset tics\nunset key\nunset colorbox\nset cbrange [0:1]\n"
      "set palette defined (0 'white', 1 '" +
      std::string(kRegion) + "')\n";
  if (cap) {
    const double e = cap->max_tilt_deg * 1.15;
    const Vec3 axis = cap->axis;
    r.width_cm = r.height_cm = 8.5;
    body += "set xrange [" + num(-e) + ":" + num(e) + "]\nset yrange [" + num(-e) + ":" + num(e) +
            "]\n"
            "set object 1 circle at 0,0 size " +
            num(cap->max_tilt_deg) + " fillcolor rgb '" + kRegion + "' fillstyle solid border lc rgb '" + kEdge +
            "' behind\n"
            "set label 1 'tilt from (" +
            num(axis.x()) + ", " + num(axis.y()) + ", " + num(axis.z()) +
            "), azimuth from e_{/*1.1 1}' at graph 0, graph 1.02 left\n"
            "set label 2 'e_{/*1.1 1}' at " +
            num(e * 0.97) + ",0 center front\nset label 3 'e_{/*1.1 2}' at 0," + num(e * 0.97) + " center front\n";
    int n = 4;
    for (double t = 10; t <= cap->max_tilt_deg; t += 10)
      body += "set label " + std::to_string(n++) + " '" + num(t) + "°' at " + num(t * std::cos(60 * kDeg)) + "," +
              num(t * std::sin(60 * kDeg)) + " center front font ',7' tc rgb '" + kEdge + "'\n";
    body += panel_plot(0, shaded, false, q.run_order);
  } else {
    r.width_cm = 17.5;
    r.height_cm = 9;
    body += "set xrange [-1.2:1.2]\nset yrange [-1.2:1.2]\nset multiplot layout 1,2\n";
    const char* titles[2] = {"(a) z ≥ 0, seen from +z", "(b) z < 0, seen from above through the meter"};
    for (int p = 0; p < 2; ++p) {
      body += "set label 1 '" + std::string(titles[p]) +
              "' at graph 0, graph 1.02 left\n"
              "set label 2 '+x' at 1.1,0 center\nset label 3 '+y' at 0,1.1 center\nset label 4 '−x' at -1.1,0 center\n"
              "set label 5 '−y' at 0,-1.1 center\n" +
              panel_plot(p, shaded, true, q.run_order);
    }
    body += "unset multiplot\n";
  }
  r.body = body;
  return r;
}

// A figure's files must not replace its inputs (a plan.csv drawn as plan.pdf: the data are
// plan_positions.csv and so on, but a user's file may still carry such a name).
void refuse_overwriting(const PlotRequest& q, const PlotResult& r) {
  namespace fs = std::filesystem;
  std::vector<std::string> outputs{r.stem + ".gp", r.stem + ".pdf", r.stem + ".png", r.stem + ".svg"};
  for (const auto& d : r.data) outputs.push_back(d.file);
  for (const std::string& input : {q.name, q.log, q.calibration}) {
    std::error_code ec;
    if (input.empty() || !fs::exists(input, ec)) continue;
    for (const auto& o : outputs)
      if (fs::exists(fs::path(r.folder) / o, ec) && fs::equivalent(fs::path(r.folder) / o, input, ec))
        throw UsageError(words("{out} ") + display_name(q.out) + " would write " + o + " over the input " +
                         display_name(input));
  }
}

}  // namespace

PlotResult plot(const PlotRequest& q) {
  PlotResult r = draw(q);
  refuse_overwriting(q, r);
  return r;
}

}  // namespace scalcal::commands
