// octahedral: the uniform-projection orbits of the 48 signed permutations of the axes (paper,
// Fig. 4): 6 axis positions, 12 edge positions (sqrt2/2 on two axes), 8 diagonal positions
// (sqrt3/3 on three), with multiplicities axes, edges, diagonals (numbers or symbols).
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"

namespace scalcal::symbolic {

using GiNaC::ex;

namespace {

std::vector<WeightedPoint> octahedral_points(const ex& axes, const ex& edges, const ex& diagonals) {
  std::vector<WeightedPoint> pts;
  for (int axis = 0; axis < 3; ++axis)
    for (int s : {1, -1}) {
      Point v{0, 0, 0};
      v[axis] = s;
      pts.push_back({axes, v});
    }
  const ex e = GiNaC::sqrt(ex(2)) / 2, d = GiNaC::sqrt(ex(3)) / 3;
  for (int axis = 0; axis < 3; ++axis)
    for (int s1 : {1, -1})
      for (int s2 : {1, -1}) {
        Point v{0, 0, 0};
        v[axis] = s1 * e;
        v[(axis + 1) % 3] = s2 * e;
        pts.push_back({edges, v});
      }
  for (int s1 : {1, -1})
    for (int s2 : {1, -1})
      for (int s3 : {1, -1}) pts.push_back({diagonals, Point{s1 * d, s2 * d, s3 * d}});
  return pts;
}

// A multiplicity: a non-negative integer or a symbol.
int multiplicity(const ParamMap& p, const std::string& key) {
  return is_number(p.at(key)) ? integer_param(p, key, 0, 1000000) : -1;
}

}  // namespace

Family octahedral_family() {
  Family f;
  f.name = "octahedral";
  f.summary = "orbits of the axes (6), edges (12) and diagonals (8) with multiplicities";
  f.params = {{"axes", "1", "multiplicity of the 6 axis positions"},
              {"edges", "1", "multiplicity of the 12 edge positions (projections sqrt(2)/2)"},
              {"diagonals", "0", "multiplicity of the 8 diagonal positions (projections sqrt(3)/3)"}};
  f.instance = [](const ParamMap& p) {
    for (const char* k : {"axes", "edges", "diagonals"}) multiplicity(p, k);  // validates numbers
    const ex a = p.at("axes"), e = p.at("edges"), d = p.at("diagonals");
    const auto points = octahedral_points(a, e, d);
    return FamilyInstance{GiNaC::expand(6 * a + 12 * e + 8 * d), moment_matrix(points), point_moments(points)};
  };
  f.numeric = [](const ParamMap& p) -> std::optional<Program> {
    const int a = multiplicity(p, "axes"), e = multiplicity(p, "edges"), d = multiplicity(p, "diagonals");
    if (a < 0 || e < 0 || d < 0) return std::nullopt;
    return Program::octahedral(a, e, d);
  };
  return f;
}

}  // namespace scalcal::symbolic
