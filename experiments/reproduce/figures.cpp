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
  return {e.family,          CsvWriter::text(e.name), CsvWriter::text(e.source), std::to_string(v.positions),
          csv_num(v.det_K), csv_num(v.D), csv_num(v.A), csv_num(v.E), csv_num(v.S),
          csv_num(v.theta_bias), csv_num(v.theta_scale), csv_num(v.theta_nonorth)};
}

void render_figure(Context& ctx, const std::string& name, const std::string& comment, const std::string& body, int width,
                   int height) {
  ctx.progress.stage("rendering " + name);
  plots::FigureSpec spec;
  spec.name = name;
  spec.comment = comment;
  spec.body = body;
  spec.width = width;
  spec.height = height;
  plots::render(ctx.options.out, spec);
}

namespace {

std::string series(const std::string& family_test, int column, const std::string& how, const std::string& title) {
  return "'fig4_programs.csv' skip 1 using 4:(" + family_test + " ? $" + std::to_string(column) + " : NaN) " + how +
         " title " + plots::gp_quote(title);
}

}  // namespace

std::string class_plot(int column, const Context& ctx, bool with_limit) {
  using namespace plots::style;
  std::vector<std::string> parts = {
      series("strcol(1) eq 'uniform'", column,
             std::string("with points pt 5 ps 1.3 lc rgb '") + uniform + "'", "uniform projections (1, √2/2, √3/3)"),
      series("strcol(1) eq 'rotation'", column, std::string("with points pt 3 ps 1.8 lw 2 lc rgb '") + rotation + "'",
             "rotation about each axis [12]"),
  };
  parts.push_back(series("strcol(1) eq 'optimised'", column,
                         std::string("with points pt 9 ps 1.5 lc rgb '") + optimised + "'",
                         "optimised, D-criterion (scalcal)"));
  parts.push_back(series("strcol(2) eq 'dodecahedral-12'", column,
                         std::string("with points pt 7 ps 2.2 lc rgb '") + jig + "'", "dodecahedral jig (12)"));
  parts.push_back(series("strcol(2) eq 'icosahedral-20'", column,
                         std::string("with points pt 13 ps 2.4 lc rgb '") + jig + "'", "icosahedral jig (20)"));
  parts.push_back("'fig4_random.csv' skip 1 using 1:" + std::to_string(column == 5 ? 4 : 5) +
                  " with lines dt 2 lw 2 lc rgb '" + random + "' title " +
                  plots::gp_quote("best of " + std::to_string(ctx.random_count) + " random programs"));
  if (with_limit)
    parts.push_back(std::string("LIMIT with lines lw 2 lc rgb '") + limit + "' title 'limit 61509375/4 ≈ 1.5377·10^7'");
  std::string plot = "plot ";
  for (std::size_t i = 0; i < parts.size(); ++i) plot += (i ? ", \\\n     " : "") + parts[i];
  return plot + "\n";
}

}  // namespace scalcal::reproduce
