// Mounting frames (kinematics.hpp).
#include "numeric/bench/kinematics.hpp"

#include "numeric/region/region.hpp"

namespace scalcal {

Mat3 mounting_rotation(const Vec3& up) {
  const auto [e1, e2] = azimuth_frame(up);
  Mat3 M;
  M.row(0) = e1.transpose();
  M.row(1) = e2.transpose();
  M.row(2) = up.transpose();
  return M;
}

}  // namespace scalcal
