// Where each position of a program may move during a local optimisation: anywhere on the sphere,
// within a zone (its tilt from an axis between two angles: a linear constraint on eta), or not at
// all (a position on a finite candidate of a restricted bench). Empty bounds: all free.
#pragma once
#include <vector>

#include "numeric/model/model.hpp"

namespace scalcal {

struct PositionBound {
  enum class Kind { Free, Zone, Fixed };
  Kind kind = Kind::Free;
  Vec3 axis{0, 0, 1};                // Zone: unit axis
  double lower = -1.0, upper = 1.0;  // Zone: cos(max tilt) <= axis . eta <= cos(min tilt)
};

using PositionBounds = std::vector<PositionBound>;

}  // namespace scalcal
