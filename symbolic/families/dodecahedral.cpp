// dodecahedral: the 12-face jig. Positions are the face normals of a regular dodecahedron, the
// icosahedron's vertices (0, +-1, +-phi) and cyclic permutations, normalised; the orientation
// of numeric/program.hpp (three two-fold axes along the meter's axes).
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"
#include "symbolic/jigs.hpp"

namespace scalcal::symbolic {

using GiNaC::ex;

std::vector<WeightedPoint> dodecahedral_points() {
  const ex phi = (1 + GiNaC::sqrt(ex(5))) / 2;
  const ex norm = GiNaC::sqrt(1 + phi * phi);
  std::vector<WeightedPoint> pts;
  for (int c = 0; c < 3; ++c)
    for (int s1 : {1, -1})
      for (int s2 : {1, -1}) {
        Point v;
        v[c] = 0;
        v[(c + 1) % 3] = s1 / norm;
        v[(c + 2) % 3] = s2 * phi / norm;
        pts.push_back({1, v});
      }
  return pts;
}

std::vector<Family> dodecahedral_families() {
  Family f;
  f.name = "dodecahedral";
  f.summary = "12-face jig: the face normals of a regular dodecahedron (12 positions)";
  f.instance = [](const ParamMap&) {
    const auto points = dodecahedral_points();
    return FamilyInstance{12, moment_matrix(points), point_moments(points)};
  };
  f.numeric = [](const ParamMap&) -> std::optional<Program> { return Program::dodecahedral(); };
  return {f};
}

}  // namespace scalcal::symbolic
