// icosahedral: the 20-face jig. Positions are the face normals of a regular icosahedron, the
// dodecahedron's vertices (+-1, +-1, +-1) and (0, +-1/phi, +-phi) cyclic, over sqrt 3; the
// orientation of numeric/program.hpp (three two-fold axes along the meter's axes).
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"
#include "symbolic/jigs.hpp"

namespace scalcal::symbolic {

using GiNaC::ex;

std::vector<WeightedPoint> icosahedral_points() {
  const ex phi = (1 + GiNaC::sqrt(ex(5))) / 2;
  const ex inv_phi = phi - 1;  // 1/phi, written so no radical lands in a denominator
  const ex norm = GiNaC::sqrt(ex(3));
  std::vector<WeightedPoint> pts;
  for (int s1 : {1, -1})
    for (int s2 : {1, -1})
      for (int s3 : {1, -1}) pts.push_back({1, Point{s1 / norm, s2 / norm, s3 / norm}});
  for (int c = 0; c < 3; ++c)
    for (int s1 : {1, -1})
      for (int s2 : {1, -1}) {
        Point v;
        v[c] = 0;
        v[(c + 1) % 3] = s1 * inv_phi / norm;
        v[(c + 2) % 3] = s2 * phi / norm;
        pts.push_back({1, v});
      }
  return pts;
}

std::vector<Family> icosahedral_families() {
  Family f;
  f.name = "icosahedral";
  f.summary = "20-face jig: the face normals of a regular icosahedron (20 positions)";
  f.instance = [](const ParamMap&) {
    const auto points = icosahedral_points();
    return FamilyInstance{20, moment_matrix(points), point_moments(points)};
  };
  f.numeric = [](const ParamMap&) -> std::optional<Program> { return Program::icosahedral(); };
  return {f};
}

}  // namespace scalcal::symbolic
