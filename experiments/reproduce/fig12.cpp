// fig12 (new, issue 11): what a restricted bench costs. For caps (tilt up to theta from one axis),
// bands (elevation within theta of a plane) and the six remounted faces (tilt up to theta from each
// axis): (a) each criterion's limit on the region relative to the sphere's, (b) the RMS errors
// theta_q of the region's D-optimal measure relative to the sphere's, (c) the smallest N whose best
// program comes within 1 % of the region's D limit. Data: fig12.csv, fig12_thetas.csv, fig12_n.csv.
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <tuple>

#include "experiments/reproduce/figures.hpp"
#include "experiments/reproduce/format.hpp"
#include "numeric/program/catalogue.hpp"
#include "numeric/region/region_limit.hpp"
#include "numeric/region/region_limits.hpp"
#include "numeric/region/region_synthesis.hpp"
#include "numeric/synthesis/workers.hpp"
#include "plots/csv_writer.hpp"
#include "plots/figure.hpp"

namespace scalcal::reproduce {
namespace {

// Angles as a user types them: "30", "22.5".
std::string angle(double deg) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", deg);
  return s;
}

struct Family {
  const char* name;   // cap, band, faces
  const char* label;  // for the key
  std::vector<double> angles;
  std::string spec(double theta) const {
    if (std::string(name) == "band") return "band:" + angle(90 - theta) + ":" + angle(90 + theta);
    return std::string(name) + ":" + angle(theta);
  }
};

std::vector<Family> families(bool quick) {
  if (quick) return {{"cap", "cap", {30, 90}}, {"band", "band", {30}}, {"faces", "six faces", {20}}};
  return {{"cap", "cap", {10, 20, 30, 45, 60, 90, 120, 135, 150, 180}},
          {"band", "band", {10, 20, 30, 45, 60, 90}},
          {"faces", "six faces", {5, 10, 20, 30, 45}}};
}

// sqrt(max K(r,r)) over each group: the measure's normalised RMS errors.
std::array<double, 3> thetas(const Mat9& K) {
  std::array<double, 3> out{};
  for (int g = 0; g < 3; ++g)
    for (int r : group_members<Paper9Model>(static_cast<ParameterGroup>(g)))
      out[g] = std::max(out[g], std::sqrt(K(r, r)));
  return out;
}

// The smallest N of `sizes` whose best program on the region comes within 1 % of `limit`.
std::optional<std::pair<int, double>> smallest_n(const Region& region, double limit, const std::vector<int>& sizes,
                                                 const Context& ctx, int threads) {
  for (int n : sizes) {
    SynthesisOptions o;
    o.positions = n;
    o.criterion = CriterionKind::D;
    o.starts = ctx.options.quick ? 2 : 4;
    o.seed = ctx.options.seed;
    o.threads = threads;
    const SynthesisResult r = synthesize_on_region(o, region);
    if (r.value <= 1.01 * limit) return std::make_pair(n, r.value);
  }
  return std::nullopt;
}

// fig12's gnuplot script: three panels on the page width over fig12.csv, fig12_thetas.csv and
// fig12_n.csv; largest_n is the N scan's end, drawn as a line in panel (c).
std::string fig12_script(const std::vector<Family>& fams, int largest_n) {
  // Three panels on the page width. Colour and point say the criterion (a), the error group (b) or the
  // family (c); the dash says the family, so the keys need seven lines, not twelve.
  using namespace plots::style;
  const char* dashes[] = {"1", "2", "3"};  // cap solid, band dashed, faces dotted
  const char* family_colours[] = {black, dark, medium};
  std::string body =
      "set multiplot\nset grid\nset xrange [0:185]\nset xtics 30\nset xlabel 'half-angle φ (degrees)'\n"
      "set key top right Left reverse samplen 2.5 width -1\nset tmargin at screen 0.91\nset bmargin at screen 0.16\n"
      "set lmargin at screen 0.075\nset rmargin at screen 0.325\nset label 1 '(a)' at graph 0, graph 1.04 left front\n"
      "set logscale y\nset format y '10" +
      plots::sup("%T") +
      "'\nset ylabel 'limit on the region / on the sphere'\n"
      "plot ";
  int k = 0;
  for (std::size_t fi = 0; fi < fams.size(); ++fi)
    for (std::size_t ci = 0; ci < kCriteria.size(); ++ci) {
      const std::string cn(criterion_name(kCriteria[ci]));
      body += std::string(k++ ? ", \\\n     " : "") + "'fig12.csv' skip 1 using 2:((strcol(1) eq '" + fams[fi].name +
              "' && strcol(4) eq '" + cn + "') ? " + (kCriteria[ci] == CriterionKind::D ? "$6**(1.0/9)" : "$6") +
              " : NaN) with linespoints dt " + dashes[fi] + " pt " + std::to_string(criterion_point[ci]) +
              " ps 0.6 lw 1.5 lc rgb '" + criterion[ci] + "' " +
              (fi == 0 ? "title " + plots::gp_quote(kCriteria[ci] == CriterionKind::D ? "D^{1/9}" : cn)
                       : std::string("notitle"));
    }
  auto family_keys = [&] {
    std::string keys;
    for (std::size_t fi = 0; fi < fams.size(); ++fi)
      keys += ", \\\n     NaN with lines dt " + std::string(dashes[fi]) + " lw 1.5 lc rgb 'black' title " +
              plots::gp_quote(fams[fi].label);
    return keys;
  };
  body += family_keys();
  body += "\nset lmargin at screen 0.41\nset rmargin at screen 0.66\nset label 1 '(b)'\nset ylabel '" +
          std::string(theta_q) + " on the region / on the sphere'\nplot ";
  const char* thetas[] = {theta_bias, theta_scale, theta_nonorth};
  k = 0;
  for (std::size_t fi = 0; fi < fams.size(); ++fi)
    for (int g = 0; g < 3; ++g)
      body += std::string(k++ ? ", \\\n     " : "") + "'fig12_thetas.csv' skip 1 using 2:(strcol(1) eq '" +
              fams[fi].name + "' ? $" + std::to_string(7 + g) + " : NaN) with linespoints dt " + dashes[fi] + " pt " +
              std::to_string(criterion_point[g + 1]) + " ps 0.6 lw 1.5 lc rgb '" + group[g] + "' " +
              (fi == 0 ? "title " + plots::gp_quote(thetas[g]) : std::string("notitle"));
  body += family_keys();
  // The scan's largest N as a line: the panel has a point to draw even when no region was reached.
  body +=
      "\nset lmargin at screen 0.745\nset rmargin at screen 0.985\nset label 1 '(c)'\nunset logscale y\n"
      "set format y '%g'\nset ylabel 'smallest N within 1 % of the D limit'\nset yrange [0:" +
      std::to_string(largest_n * 3 / 2 + 2) + "]\nplot " + std::to_string(largest_n) +
      " with lines dt 4 lw 1.5 lc rgb '" + grey + "' title 'largest N tried'";
  for (std::size_t fi = 0; fi < fams.size(); ++fi)
    body += std::string(", \\\n     ") + "'fig12_n.csv' skip 1 using 2:(strcol(1) eq '" + fams[fi].name +
            "' ? $4 : NaN) with linespoints dt " + dashes[fi] + " pt " + std::to_string(criterion_point[fi]) +
            " ps 0.6 lw 1.5 lc rgb '" + family_colours[fi] + "' title " + plots::gp_quote(fams[fi].label);
  body += "\nunset multiplot\n";
  return body;
}

// fig12's figure and its text in the report, once its CSV files are written.
void report_fig12(Context& ctx, const std::vector<int>& n_scan, const std::string& n_table) {
  auto& rep = ctx.report;
  const std::string body = fig12_script(families(ctx.options.quick), n_scan.back());
  render_figure(ctx, "fig12", "what a restricted bench costs: region limits, RMS errors and the N to reach them", body,
                plots::kPageWidthCm, 6.5);
  rep.figure("fig12",
             "fig12: (a) each criterion's limit on a cap (solid), a band (dashed) and the six faces (dotted) "
             "relative to the sphere's (D as its 9th root, as the CLI's efficiency, so that its 4.6·10^32 at 10° "
             "becomes 4.4·10^3 beside the others); (b) the RMS errors θ_bias, θ_scale, θ_nonorth of the region's "
             "D-optimal measure relative to the sphere's; (c) the smallest N within 1 % of the region's D "
             "limit");
  rep.paragraph(
      "Data: [fig12.csv](fig12.csv), [fig12_thetas.csv](fig12_thetas.csv), [fig12_n.csv](fig12_n.csv). A cap "
      "of half-angle φ holds the directions within φ of +z, a band those within φ of the horizontal plane, "
      "the six faces those within φ of ±x, ±y or ±z. D on a cap is a theorem's closed form "
      "(proofs/cap_d_limit.md), and so are E and S on caps up to 110.38° and 99.88° (proofs/cap_es_limits.md); "
      "D on a band is solved as a one-dimensional problem (numeric/region/zonal_d.hpp); the others are optimal "
      "measures found numerically (`scalcal limits --region` adds their proven lower bounds). The smallest N is "
      "the first of N = " +
      std::to_string(n_scan.front()) + ", " + std::to_string(n_scan.front() + 1) + ", ..., " +
      std::to_string(n_scan.back()) + " whose best program (" + std::to_string(ctx.options.quick ? 2 : 4) +
      " exchange starts) comes within 1 %:");
  rep.paragraph(n_table);
}

}  // namespace

using plots::CsvWriter;

void figure_regions(Context& ctx) {
  auto& rep = ctx.report;
  rep.heading(2, "fig12 (new): what a restricted bench costs");
  CsvWriter limits(ctx.file("fig12.csv"),
                   {"family", "theta_deg", "region", "criterion", "value", "relative_to_sphere"});
  CsvWriter errors(ctx.file("fig12_thetas.csv"),
                   {"family", "theta_deg", "region", "theta_bias", "theta_scale", "theta_nonorth", "bias_relative",
                    "scale_relative", "nonorth_relative"});
  CsvWriter sizes(ctx.file("fig12_n.csv"), {"family", "theta_deg", "region", "smallest_N", "D", "ratio"});
  // The sphere's D-optimal measure: any 4-design, e.g. the dodecahedral jig's 12 face normals.
  const std::array<double, 3> sphere_thetas = [] {
    const Evaluation ev = evaluate(resolve_program("dodecahedral-12"));
    return std::array<double, 3>{ev.theta_bias, ev.theta_scale, ev.theta_nonorth};
  }();
  RegionLimitOptions quick_limits;
  quick_limits.certify = false;  // the values only: `scalcal limits --region` proves each bound
  quick_limits.max_refinements = 3;
  std::vector<int> n_scan;  // every N from 9 up, until one comes within 1 %
  for (int n = 9; n <= (ctx.options.quick ? 12 : 40); ++n) n_scan.push_back(n);
  std::string n_table = "| region | smallest N within 1 % of the D limit | its D / limit |\n| --- | ---: | ---: |\n";
  struct LimitRow {
    std::string family;
    CriterionKind criterion;
    double theta;
    std::vector<std::string> cells;
  };
  std::vector<LimitRow> rows;
  // Every region's limits first, side by side in worker processes (region_limits.hpp): the first
  // half of the stage. Then the regions' N scans, the second half.
  struct Scan {
    std::string family, spec;
    double theta, limit;
    Region region;
  };
  std::vector<Scan> scans;  // every region once; limit is its D limit, set below
  std::vector<RegionLimitTask> tasks;
  for (const auto& f : families(ctx.options.quick))
    for (double theta : f.angles) {
      const std::string spec = f.spec(theta);
      scans.push_back({f.name, spec, theta, 0.0, parse_region({spec})});
      if (!scans.back().region.is_sphere())
        for (auto c : kCriteria) tasks.push_back({c, scans.back().region});
    }
  ctx.progress.part(0, 0.5, "region limits");
  const std::vector<RegionLimit> region_limit_values = region_limits(
      tasks, quick_limits, ctx.threads(), [&](int finished, int count) { ctx.progress.step(finished, count); });
  std::size_t next_limit = 0;
  // The limits' rows, the D measure's thetas, and the D limit each scan aims at.
  for (Scan& sc : scans) {
    const Region& region = sc.region;
    std::optional<RegionLimit> d_limit;
    for (auto c : kCriteria) {
      const RegionLimit l = region.is_sphere() ? RegionLimit{} : region_limit_values[next_limit++];
      const double value = region.is_sphere() ? criterion_limit(c).value : l.value;
      rows.push_back({sc.family,
                      c,
                      sc.theta,
                      {sc.family, csv_num(sc.theta), sc.spec, std::string(criterion_name(c)), csv_num(value),
                       csv_num(value / criterion_limit(c).value)}});
      if (c == CriterionKind::D && !region.is_sphere()) d_limit = l;
    }
    const std::array<double, 3> t = d_limit ? thetas(d_limit->K) : sphere_thetas;
    errors.row({sc.family, csv_num(sc.theta), sc.spec, csv_num(t[0]), csv_num(t[1]), csv_num(t[2]),
                csv_num(t[0] / sphere_thetas[0]), csv_num(t[1] / sphere_thetas[1]), csv_num(t[2] / sphere_thetas[2])});
    sc.limit = d_limit ? d_limit->value : criterion_limit(CriterionKind::D).value;
  }
  // Each region's N scan, one region per task in the same worker processes (the regions' scans are
  // independent, and whole scans side by side keep both cores busy where one synthesis at a time,
  // 4 starts, does not). A task returns (smallest N or 0, its D).
  ctx.progress.part(0.5, 0.5, "N scans of " + std::to_string(scans.size()) + " regions");
  const std::vector<std::vector<double>> found = run_values_in_workers(
      static_cast<int>(scans.size()), ctx.threads(), 2,
      [&](int k) {
        const Scan& sc = scans[static_cast<std::size_t>(k)];
        const auto n = smallest_n(sc.region, sc.limit, n_scan, ctx, 1);
        return std::vector<double>{n ? static_cast<double>(n->first) : 0.0, n ? n->second : 0.0};
      },
      [&](int finished, int count) { ctx.progress.step(finished, count); });
  for (std::size_t k = 0; k < scans.size(); ++k) {
    const Scan& sc = scans[k];
    const bool reached = found[k][0] > 0;
    const int n = static_cast<int>(found[k][0]);
    const double d = found[k][1];
    sizes.row({sc.family, csv_num(sc.theta), sc.spec, reached ? std::to_string(n) : "", reached ? csv_num(d) : "",
               reached ? csv_num(d / sc.limit) : ""});
    n_table += "| `" + sc.spec + "` | " + (reached ? std::to_string(n) : "over " + std::to_string(n_scan.back())) +
               " | " + (reached ? decimal(d / sc.limit, 5) : "") + " |\n";
  }
  // By family, then criterion, then angle: each curve is one run of rows, so gnuplot joins it.
  std::stable_sort(rows.begin(), rows.end(), [](const LimitRow& a, const LimitRow& b) {
    return std::tie(a.family, a.criterion) < std::tie(b.family, b.criterion);
  });
  for (const auto& row : rows) limits.row(row.cells);
  limits.close();
  errors.close();
  sizes.close();

  report_fig12(ctx, n_scan, n_table);
}

}  // namespace scalcal::reproduce
