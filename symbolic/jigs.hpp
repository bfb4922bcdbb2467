// The exact positions of the two polyhedral jigs, shared by their families and by the proof
// that their information matrix does not depend on the meter's orientation in the jig.
#pragma once
#include <vector>

#include "symbolic/exact.hpp"

namespace scalcal::symbolic {

std::vector<WeightedPoint> dodecahedral_points();
std::vector<WeightedPoint> icosahedral_points();

}  // namespace scalcal::symbolic
