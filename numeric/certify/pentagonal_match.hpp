// D at N = 12 cannot go through the moment equations (21 coordinates after the rotation gauge for
// 24 equations): its optima form a continuum, the two poles with two regular pentagons at heights
// +-1/sqrt 5 turned by any two angles (proof.pentagonal_designs; the icosahedron is one of them).
// This fits that family to a program and encloses, in MPFI, how far the exact member is.
#pragma once
#include <optional>

#include "numeric/certify/interval.hpp"
#include "numeric/certify/sphere_chart.hpp"
#include "numeric/program/program.hpp"

namespace scalcal::certify_detail {

// The inf-norm radius, in the chart coordinates of `chart` (built on `program`), within which an
// exact member of the pentagonal family lies, one point per position; nullopt when the program is
// not within 1e-4 of a member.
std::optional<Real> radius_to_pentagonal_design(const Program& program, const SphereChart& chart);

}  // namespace scalcal::certify_detail
