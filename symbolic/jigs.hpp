// The exact face normals of the printable polyhedral jigs (Platonic, Archimedean and Catalan solids
// a lab prints and tips face to face) and the orientation of the meter in a jig. Shared by their
// families (families/printable_jigs.cpp), the `jig` command and the proofs of which limits they reach.
#pragma once
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "symbolic/exact.hpp"

namespace scalcal::symbolic {

std::vector<WeightedPoint> dodecahedral_points();
std::vector<WeightedPoint> icosahedral_points();

struct JigSolid {
  std::string name;      // the family is jig:NAME
  std::string faces;     // "6 squares + 8 triangles"
  std::string symmetry;  // "octahedral" or "icosahedral": the rotation group its face normals are orbits of
  std::vector<WeightedPoint> normals;  // unit face normals in the jig's frame, one per face
};

// Every printable jig, in the order of the issue that asked for them.
const std::vector<JigSolid>& printable_jigs();

// The meter's orientation in a jig as the 3x3 matrix O whose rows are the meter's axes in jig
// coordinates (a face normal n is then the position O n). Text: "identity"; "aa:X,Y,Z,DEG" (the meter
// turned by DEG degrees about the axis (X, Y, Z) of the jig); "q:W,X,Y,Z" (the same by a quaternion,
// normalised here); "rows:R11,R12,...,R33" (O itself, as `jig` prints it). Components are GiNaC
// expressions, so symbols give closed forms. Throws InputError for a malformed or improper one.
GiNaC::matrix orientation_matrix(const std::string& text, GiNaC::parser& reader);

// O n for each normal, each coordinate canonical.
std::vector<WeightedPoint> oriented(const GiNaC::matrix& O, const std::vector<WeightedPoint>& normals);

}  // namespace scalcal::symbolic
