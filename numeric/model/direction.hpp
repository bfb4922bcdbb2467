// The unit direction of a measured or given vector, to full precision at any scale.
#pragma once
#include <cmath>
#include <optional>

#include "numeric/model/model.hpp"

namespace scalcal {

// Divided by its largest component first, so that subnormal components (1e-323, where v / |v| keeps
// only a few bits) keep their ratios and 1e300 does not overflow; nullopt for the zero vector and for
// a vector with a component that is not finite.
inline std::optional<Vec3> unit_direction(const Vec3& v) {
  if (!v.allFinite()) return std::nullopt;
  const double largest = v.cwiseAbs().maxCoeff();
  if (!(largest > 0)) return std::nullopt;
  const Vec3 scaled = v / largest;
  return Vec3(scaled / scaled.norm());
}

}  // namespace scalcal
