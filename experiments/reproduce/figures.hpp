// The figures and tables of `scalcal reproduce`, one stage each (fig456.cpp ... tables.cpp,
// summary.cpp), and the helpers they share (figures.cpp): the CSV columns of a program, the plot of
// the program classes, and rendering through plots/.
#pragma once
#include <string>
#include <vector>

#include "experiments/reproduce/context.hpp"

namespace scalcal::reproduce {

void figures_4_5_6(Context& ctx);
void figure_7(Context& ctx);
void figure_8(Context& ctx);
void figure_9(Context& ctx);
void figure_limits(Context& ctx);  // fig10: optimum of each criterion against N, with its limit
void figure_sphere(Context& ctx);  // fig11: the optimal N = 12 and 18 programs on the sphere
void figure_regions(Context& ctx); // fig12: what a restricted bench (cap, band, faces) costs
void real_data(Context& ctx);      // fig13: the Xsens log calibrated end to end
void tables_1_2_3(Context& ctx);
void summary(Context& ctx);        // the paper's stated numbers beside scalcal's, at the top

// The CSV columns describing one program (family, name, source, N, det K, D, A, E, S, thetas).
std::vector<std::string> entry_header();
std::vector<std::string> entry_cells(const Entry& e);

// The gnuplot `plot` command drawing column `column` of fig4_programs.csv for each program class of
// Fig. 4, and the random programs' dashed line (their D column when column is 6, else det K).
std::string class_plot(int column, const Context& ctx, bool with_limit);

// Paths are relative to the output folder; the figure scripts run there.
void render_figure(Context& ctx, const std::string& name, const std::string& comment, const std::string& body,
                   int width = 1100, int height = 750);

}  // namespace scalcal::reproduce
