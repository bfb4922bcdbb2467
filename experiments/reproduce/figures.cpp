// What every figure stage shares: its CSV, its script and its REPORT.md section (figures.hpp).
#include "experiments/reproduce/figures.hpp"

#include "experiments/reproduce/format.hpp"
#include "plots/csv_writer.hpp"
#include "plots/figure.hpp"

namespace scalcal::reproduce {

using plots::CsvWriter;

std::vector<std::string> entry_header() {
  return {"family", "name", "source", "N", "det_K", "D", "A", "E", "S", "theta_bias", "theta_scale", "theta_nonorth"};
}

std::vector<std::string> entry_cells(const Entry& e) {
  const auto& v = e.ev;
  return {e.family,
          CsvWriter::text(e.name),
          CsvWriter::text(e.source),
          std::to_string(v.positions),
          csv_num(v.raw(CriterionKind::D)),
          csv_num(v.value(CriterionKind::D)),
          csv_num(v.value(CriterionKind::A)),
          csv_num(v.value(CriterionKind::E)),
          csv_num(v.value(CriterionKind::S)),
          csv_num(v.theta_bias),
          csv_num(v.theta_scale),
          csv_num(v.theta_nonorth)};
}

void render_figure(Context& ctx, const std::string& name, const std::string& comment, const std::string& body,
                   double width_cm, double height_cm) {
  ctx.progress.detail("rendering " + name);
  plots::FigureSpec spec;
  spec.name = name;
  spec.comment = comment;
  spec.body = body;
  spec.width_cm = width_cm;
  spec.height_cm = height_cm;
  plots::render(ctx.options.out, spec);
}

std::string random_title(const Context& ctx) {
  std::string count = std::to_string(ctx.random_count);
  // 100000 -> 10^5: a round count reads as a power of ten.
  if (count.size() > 3 && count.find_first_not_of('0', 1) == std::string::npos && count[0] == '1')
    count = "10" + plots::sup(std::to_string(count.size() - 1));
  std::string title = "best of " + count + " random";
  if (!ctx.random_best.empty()) title += " (N ≤ " + std::to_string(ctx.random_best.rbegin()->first) + ")";
  return title;
}

namespace {

std::string series(const std::string& family_test, int column, const std::string& how, const std::string& title) {
  return "'fig4_programs.csv' skip 1 using 4:(" + family_test + " ? $" + std::to_string(column) + " : NaN) " + how +
         " " + title;
}

}  // namespace

std::string class_plot(const ClassPlot& p, const Context& ctx) {
  using namespace plots::style;
  auto title = [&p](const std::string& full, const std::string& brief = "") {
    return p.titles ? "title " + plots::gp_quote(p.short_titles && !brief.empty() ? brief : full)
                    : std::string("notitle");
  };
  auto line_title = [&p, &title](const std::string& full) { return p.line_titles ? title(full) : "notitle"; };
  std::vector<std::string> parts;
  if (p.limit)
    parts.push_back(std::string("LIMIT with lines lw 2 lc rgb '") + limit + "' " + line_title("limit 61509375/4"));
  parts.push_back(series("strcol(1) eq 'uniform'", p.column,
                         std::string("with points pt 5 ps 0.75 lc rgb '") + uniform + "'",
                         title("uniform projections", "uniform")));
  if (p.random)
    parts.push_back("'fig4_random.csv' skip 1 using 1:" + std::to_string(p.column == 6 ? 5 : 4) +
                    " with lines dt 2 lw 2 lc rgb '" + random + "' " + line_title(random_title(ctx)));
  parts.push_back(series("strcol(1) eq 'rotation'", p.column,
                         std::string("with points pt 3 ps 1.1 lw 2 lc rgb '") + rotation + "'",
                         title("rotation about each axis [12]", "rotation [12]")));
  parts.push_back(series("strcol(1) eq 'optimised'", p.column,
                         std::string("with points pt 9 ps 0.8 lc rgb '") + optimised + "'",
                         title("optimised for D (scalcal)", "optimised for D")));
  parts.push_back(series("strcol(2) eq 'dodecahedral-12'", p.column,
                         std::string("with points pt 6 ps 1.6 lw 2 lc rgb '") + jig + "'",
                         title("dodecahedral jig (N = 12)", "dodecahedral jig")));
  parts.push_back(series("strcol(2) eq 'icosahedral-20'", p.column,
                         std::string("with points pt 12 ps 1.9 lw 2 lc rgb '") + jig + "'",
                         title("icosahedral jig (N = 20)", "icosahedral jig")));
  parts.push_back(series("strcol(1) eq 'printable'", p.column,
                         std::string("with points pt 4 ps 0.9 lw 1.5 lc rgb '") + jig + "'",
                         title("printable jigs (scalcal)", "printable jigs")));
  std::string plot = "plot ";
  for (std::size_t i = 0; i < parts.size(); ++i) plot += (i ? ", \\\n     " : "") + parts[i];
  return plot + "\n";
}

}  // namespace scalcal::reproduce
