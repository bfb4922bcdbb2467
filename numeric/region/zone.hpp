// A zone of the sphere: the directions whose angle from an axis lies between two tilts. Caps
// (0..DEG), bands (LO..HI) and the whole sphere (0..180) are zones; a region is a union of zones
// and finite candidate sets (numeric/region/region.hpp).
#pragma once
#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "numeric/model/model.hpp"

namespace scalcal {

struct Zone {
  Vec3 axis{0.0, 0.0, 1.0};  // unit
  double min_tilt_deg = 0.0;
  double max_tilt_deg = 180.0;

  // The tilt of x (unit) from the axis, in degrees; atan2 keeps it accurate near 0 and 180.
  double tilt_deg(const Vec3& x) const {
    return std::atan2(axis.cross(x).norm(), axis.dot(x)) * 180.0 / 3.14159265358979323846;
  }
  // tolerance_deg lets a position written with 6 decimals sit on the boundary it was meant for.
  bool contains(const Vec3& x, double tolerance_deg = 1e-6) const {
    const double t = tilt_deg(x);
    return t >= min_tilt_deg - tolerance_deg && t <= max_tilt_deg + tolerance_deg;
  }
  bool is_sphere() const { return min_tilt_deg <= 0.0 && max_tilt_deg >= 180.0; }
};

}  // namespace scalcal
