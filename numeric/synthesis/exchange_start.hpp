// A start for models whose optima put several positions on one direction (axis6: the six axes
// k times each): a random program exchanged onto a spiral grid of the sphere, where coincident
// positions are as easy to reach as any others, then the local solver. A smooth local solver from
// a random program rarely merges positions: for axis6, D at N = 18, 10 of 22 Newton starts stalled
// at 1.125 times the limit and none reached it.
#pragma once
#include <cmath>
#include <vector>

#include "numeric/criteria/registry.hpp"
#include "numeric/model/registry.hpp"
#include "numeric/program/program.hpp"
#include "numeric/synthesis/exchange.hpp"

namespace scalcal {

inline constexpr int kExchangeGridPoints = 2000;

// n points on the golden spiral: nearly uniform, no two alike, none on a coordinate axis (so the
// grid favours no answer).
inline std::vector<Vec3> spiral_grid(int n) {
  std::vector<Vec3> out;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n, r = std::sqrt(1.0 - z * z), phi = golden * i;
    out.emplace_back(r * std::cos(phi), r * std::sin(phi), z);
  }
  return out;
}

// `start` exchanged onto the spiral grid for the criterion under the model.
inline Program exchanged_start(CriterionKind criterion, ModelKind model, const Program& start) {
  static const std::vector<Vec3> grid = spiral_grid(kExchangeGridPoints);
  return Program{exchange(criterion, grid, start.positions, 0, 100, model).positions};
}

}  // namespace scalcal
