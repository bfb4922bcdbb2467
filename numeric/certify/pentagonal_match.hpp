// D at N = 12 cannot go through the moment equations (21 coordinates after the rotation gauge for
// 24 equations): its optima form a continuum, the two poles with two regular pentagons at heights
// +-1/sqrt 5 turned by any two angles (proof.pentagonal_designs; the icosahedron is one of them).
// This fits that family to a program and encloses, in MPFI, the exact member's positions.
#pragma once
#include <optional>

#include <vector>

#include "numeric/certify/certificate_tools.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::certify_detail {

// An exact member of the pentagonal family, one point per position of the program, its positions
// enclosed; nullopt when the program is not within 1e-4 of a member.
std::optional<std::vector<IPoint>> pentagonal_design_near(const Program& program);

}  // namespace scalcal::certify_detail
