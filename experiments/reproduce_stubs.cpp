#include "experiments/reproduce.hpp"
namespace scalcal::reproduce {
void figure_7(Context&) {}
void figure_8(Context&) {}
void figure_9(Context&) {}
void figure_limits(Context&) {}
void figure_sphere(Context&) {}
void tables_1_2_3(Context&) {}
void summary(Context&) {}
}
