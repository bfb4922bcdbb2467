// The three orbits of the octahedral group with uniform projections, exactly: the 6 axes, the 12
// edges (sqrt 2/2 on two axes) and the 8 diagonals (sqrt 3/3 on three), each point with one weight.
// The octahedral family and the printable jigs are made of them, in this order of points.
#pragma once
#include <vector>

#include "symbolic/exact.hpp"

namespace scalcal::symbolic {

std::vector<WeightedPoint> axis_orbit(const GiNaC::ex& weight = 1);
std::vector<WeightedPoint> edge_orbit(const GiNaC::ex& weight = 1);
std::vector<WeightedPoint> diagonal_orbit(const GiNaC::ex& weight = 1);

}  // namespace scalcal::symbolic
