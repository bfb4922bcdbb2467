// octahedral: the uniform-projection orbits of the 48 signed permutations of the axes (paper,
// Fig. 4): 6 axis positions, 12 edge positions (sqrt2/2 on two axes), 8 diagonal positions
// (sqrt3/3 on three), with multiplicities axes, edges, diagonals (numbers or symbols).
#include "symbolic/exact.hpp"
#include "symbolic/family.hpp"
#include "symbolic/octahedral_orbits.hpp"

namespace scalcal::symbolic {

using GiNaC::ex;

namespace {

std::vector<WeightedPoint> octahedral_points(const ex& axes, const ex& edges, const ex& diagonals) {
  std::vector<WeightedPoint> pts = axis_orbit(axes);
  for (const auto& more : {edge_orbit(edges), diagonal_orbit(diagonals)})
    pts.insert(pts.end(), more.begin(), more.end());
  return pts;
}

// A multiplicity: a non-negative integer or a symbol.
int multiplicity(const ParamMap& p, const std::string& key) {
  return is_number(p.at(key)) ? integer_param(p, key, 0, 1000000) : -1;
}

}  // namespace

std::vector<Family> octahedral_families() {
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
  return {f};
}

}  // namespace scalcal::symbolic
