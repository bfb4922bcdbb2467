// Gravity's direction at each still pose (gravity_poses.hpp).
#include "numeric/gyro/gravity_poses.hpp"

#include <cmath>

#include "numeric/io/input_error.hpp"

namespace scalcal::gyro {

std::vector<GyroPose> gravity_poses(const RawLog& acc, const RawLog& gyro, const std::vector<StaticInterval>& intervals,
                                    const FullCorrection& correction) {
  if (acc.size() != gyro.size())
    throw InputError(gyro.file, 0,
                     "has " + std::to_string(gyro.size()) + " rows and the accelerometer's log " + acc.file + " " +
                         std::to_string(acc.size()) + ": the two logs must have the same time stamps, row by row");
  const double tolerance =
      acc.size() > 1 ? std::max(1e-6, 1e-3 * (acc.t.back() - acc.t.front()) / (acc.size() - 1)) : 1e-6;
  for (int i = 0; i < acc.size(); ++i)
    if (std::abs(acc.t[static_cast<std::size_t>(i)] - gyro.t[static_cast<std::size_t>(i)]) > tolerance)
      throw InputError(gyro.file, gyro.lines[static_cast<std::size_t>(i)],
                       "time differs from the accelerometer's log " + acc.file + " at its line " +
                           std::to_string(acc.lines[static_cast<std::size_t>(i)]) +
                           ": the two logs must have the same time stamps, row by row");
  std::vector<GyroPose> out;
  for (const StaticInterval& iv : intervals) {
    Vec3 s = Vec3::Zero();
    std::vector<Vec3> corrected;
    for (int i = iv.begin; i <= iv.end; ++i)
      if (acc.finite(i) && gyro.finite(i))
        corrected.push_back(correction.apply(acc.samples[static_cast<std::size_t>(i)]));
    if (corrected.size() < 2) continue;
    for (const Vec3& v : corrected) s += v;
    const Vec3 mean = s / static_cast<double>(corrected.size());
    double ss = 0;
    for (const Vec3& v : corrected) ss += (v - mean).squaredNorm();
    const double per_axis = std::sqrt(ss / (3.0 * static_cast<double>(corrected.size() - 1)));
    GyroPose p;
    p.begin = iv.begin;
    p.end = iv.end;
    p.gravity = mean.normalized();
    p.gravity_std = per_axis / (mean.norm() * std::sqrt(static_cast<double>(corrected.size())));
    out.push_back(p);
  }
  return out;
}

}  // namespace scalcal::gyro
