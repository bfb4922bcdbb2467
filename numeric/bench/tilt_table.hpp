// A tilt table with the meter mounted on it in one of several ways: a turntable (about the plate's
// normal) on a plate that tilts about the lab's y axis. With the mounting M (kinematics.hpp:
// mounting_rotation(up)), the tilt t and the azimuth a (degrees):
//   R = R_y(-t) R_z(-a) M,   eta = M^T (sin t cos a, sin t sin a, cos t),
// so (t, a) are the position's tilt from the mounting's up axis and its azimuth in that axis' frame,
// as `evaluate` writes them for a cap about that axis. The plate tilts either way: (t, a) and
// (-t, a + 180) measure the same position, and a plan picks whichever travels less. Shared by the
// tilt and faces benches.
#pragma once
#include <vector>

#include "numeric/bench/bench.hpp"

namespace scalcal {

inline Mat3 tilt_table_orientation(const std::vector<Mounting>& mountings, const BenchSetting& s) {
  const double a = std::isnan(s.angles[1]) ? 0.0 : s.angles[1];
  return axis_rotation(Vec3::UnitY(), -s.angles[0]) * axis_rotation(Vec3::UnitZ(), -a) *
         mountings[static_cast<std::size_t>(s.mounting)].rotation;
}

// Every (mounting, t, a) measuring eta with |t| within the tilt axis' limits; the azimuth is free at
// the mounting's pole.
inline std::vector<BenchSetting> tilt_table_settings(const std::vector<Mounting>& mountings,
                                                     const std::vector<BenchAxis>& axes, const Vec3& eta) {
  std::vector<BenchSetting> out;
  for (std::size_t m = 0; m < mountings.size(); ++m) {
    const Vec3 u = mountings[m].rotation * eta;
    const double t = std::atan2(std::hypot(u.x(), u.y()), u.z()) / kDegree;
    if (t > axes[0].hi + kLimitSlackDeg) continue;
    const int mounting = static_cast<int>(m);
    if (t < kOnAxisDeg) {
      out.push_back(BenchSetting{mounting, {0.0, std::nan("")}});
      continue;
    }
    const double tilt = std::min(t, axes[0].hi), a = std::atan2(u.y(), u.x()) / kDegree;
    out.push_back(BenchSetting{mounting, {tilt, wrap_deg(a)}});
    out.push_back(BenchSetting{mounting, {-tilt, wrap_deg(a + 180)}});
  }
  return out;
}

}  // namespace scalcal
