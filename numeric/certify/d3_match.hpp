// D at N = 14: the optimiser's 14-point 4-designs form a continuum on which the moment equations
// lose rank (23 of 24), so no square subsystem is regular there. One member is known in closed form
// (proof.d3_design): the poles and two orbits of the dihedral group D3, at heights
// z^2 = (10 +- sqrt 35)/45, turned by phi1, phi2 with cos 3 phi, sin 3 phi given by radicals. This fits
// that design (any rotation, either mirror image) to a program and encloses its positions in MPFI.
#pragma once
#include <optional>
#include <vector>

#include "numeric/certify/certificate_tools.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::certify_detail {

// The exact D3 design, one point per position of the program, its positions enclosed; nullopt when
// the program is not within 1e-4 of it (up to rotation and reflection).
std::optional<std::vector<IPoint>> d3_design_near(const Program& program);

}  // namespace scalcal::certify_detail
