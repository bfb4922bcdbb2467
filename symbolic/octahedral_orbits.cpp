// The three orbits of the octahedral group with uniform projections, exactly (octahedral_orbits.hpp).
#include "symbolic/octahedral_orbits.hpp"

namespace scalcal::symbolic {

using GiNaC::ex;

std::vector<WeightedPoint> axis_orbit(const ex& weight) {
  std::vector<WeightedPoint> pts;
  for (int axis = 0; axis < 3; ++axis)
    for (int s : {1, -1}) {
      Point v{0, 0, 0};
      v[axis] = s;
      pts.push_back({weight, v});
    }
  return pts;
}

std::vector<WeightedPoint> edge_orbit(const ex& weight) {
  const ex e = GiNaC::sqrt(ex(2)) / 2;
  std::vector<WeightedPoint> pts;
  for (int axis = 0; axis < 3; ++axis)  // the pair (axis, axis + 1), as numeric/program.hpp orders it
    for (int s1 : {1, -1})
      for (int s2 : {1, -1}) {
        Point v{0, 0, 0};
        v[axis] = s1 * e;
        v[(axis + 1) % 3] = s2 * e;
        pts.push_back({weight, v});
      }
  return pts;
}

std::vector<WeightedPoint> diagonal_orbit(const ex& weight) {
  const ex d = GiNaC::sqrt(ex(3)) / 3;
  std::vector<WeightedPoint> pts;
  for (int s1 : {1, -1})
    for (int s2 : {1, -1})
      for (int s3 : {1, -1}) pts.push_back({weight, Point{s1 * d, s2 * d, s3 * d}});
  return pts;
}

}  // namespace scalcal::symbolic
