// `scalcal plot PROGRAM [--region SPEC]... [--out FILE.pdf|png|svg]`: the figure of a program
// (commands/bench/plot.hpp), rendered by gnuplot at print size; FILE.gp, FILE.pdf, FILE.png, FILE.svg and
// the CSV data are written into FILE's folder, and their names printed.
#include <filesystem>
#include <iostream>

#include "commands/bench/plot.hpp"
#include "experiments/cli/command.hpp"
#include "experiments/cli/output_file.hpp"
#include "numeric/io/input_error.hpp"
#include "plots/figure.hpp"

namespace scalcal::cli {
namespace {

int run(const commands::Values& v) {
  const commands::PlotResult r = commands::plot(commands::plot_request(v));
  print_warnings("plot", r.warnings);
  const std::filesystem::path folder(r.folder);
  plots::FigureSpec spec;
  for (const auto& d : r.data) {
    write_output_file((folder / d.file).string(), [&](std::ostream& out) { out << d.text; });
    spec.files.push_back({d.variable, d.file});
  }
  spec.name = r.stem;
  spec.comment = r.comment;
  spec.width_cm = r.width_cm;
  spec.height_cm = r.height_cm;
  spec.body = r.body;
  spec.written_by = "scalcal plot";
  try {
    const plots::RenderedFigure f = plots::render(folder, spec);
    // Names as messages show them (control characters as '?'), one line whatever --out holds.
    std::cout << "plot (" << r.view << "): " << display_name(f.pdf.string()) << ", " << display_name(f.png.string())
              << ", " << display_name(f.svg.string()) << " (script " << display_name(f.script.string()) << ")\n";
  } catch (const std::runtime_error& e) {
    throw OutputError(std::string("plot: ") + e.what());
  }
  return 0;
}

const Registration reg(commands::plot_table(), run);

}  // namespace
}  // namespace scalcal::cli
