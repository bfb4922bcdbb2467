// The figures and tables of `scalcal reproduce`, one stage each (fig456.cpp ... tables.cpp,
// summary.cpp), and the helpers they share (figures.cpp): the CSV columns of a program, the plot of
// the program classes, and rendering through plots/ (PDF, PNG and SVG at the print size).
#pragma once
#include <string>
#include <vector>

#include "experiments/reproduce/context.hpp"

namespace scalcal::reproduce {

void figures_4_5_6(Context& ctx);
void figure_7(Context& ctx);
void figure_8(Context& ctx);
void figure_9(Context& ctx);
void figure_limits(Context& ctx);   // fig10: optimum of each criterion against N, with its limit
void figure_sphere(Context& ctx);   // fig11: the optimal N = 12 and 18 programs on the sphere
void figure_regions(Context& ctx);  // fig12: what a restricted bench (cap, band, faces) costs
void real_data(Context& ctx);       // fig13: the Xsens log calibrated end to end
void tables_1_2_3(Context& ctx);
void summary(Context& ctx);  // the paper's stated numbers beside scalcal's, at the top

// The CSV columns describing one program (family, name, source, N, det K, D, A, E, S, thetas).
std::vector<std::string> entry_header();
std::vector<std::string> entry_cells(const Entry& e);

// The gnuplot `plot` command drawing column `column` of fig4_programs.csv for each program class of
// Fig. 4 (squares first, then the line of the random programs, stars, triangles and the open jig
// symbols on top), with the limit line LIMIT underneath them all when `limit` is set.
struct ClassPlot {
  int column = 5;             // 5 det K, 6 D, 10-12 the thetas
  bool titles = true;         // key entries; Figs. 5 and 6 label their lines in the plot instead
  bool random = true;         // the random programs' dashed line (their D when column is 6, else det K)
  bool limit = false;         // the D limit, as the gnuplot variable LIMIT
  bool short_titles = false;  // "rotation [12]" for a key in three columns
  bool line_titles = true;    // the limit and random lines in the key; Fig. 5 labels them in the plot
};
std::string class_plot(const ClassPlot& p, const Context& ctx);

// "best of 10^5 random (N ≤ 36)": the random search covers fewer N than the other classes.
std::string random_title(const Context& ctx);

// Paths are relative to the output folder; the figure scripts run there. Sizes are at print size:
// plots::kColumnWidthCm for one journal column, plots::kPageWidthCm for both.
void render_figure(Context& ctx, const std::string& name, const std::string& comment, const std::string& body,
                   double width_cm, double height_cm);

}  // namespace scalcal::reproduce
