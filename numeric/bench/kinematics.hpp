// The kinematics every bench shares. Convention (docs/bench.md): the measured vector (specific force
// at rest, pointing up) is +Z of the lab; a bench setting gives the meter's orientation R (meter frame
// to lab frame) as a product of rotations R = R_A1(theta1) R_A2(theta2) ..., outer axis first, and
// the position it measures is eta = R^T (0, 0, 1), the lab's up in the meter's frame.
#pragma once
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "numeric/model/model.hpp"

namespace scalcal {

inline constexpr double kDegree = std::numbers::pi / 180.0;

// A position at most this far beyond a bench's reach is set on the limit (the step's rounding_deg
// says by how much): a program file written with six decimals puts a position designed on a cap's
// rim up to about 1e-4 degrees beyond it.
inline constexpr double kLimitSlackDeg = 1e-3;
// Below this tilt from an axis a position lies on it, and the angle about that axis is free.
inline constexpr double kOnAxisDeg = 1e-9;

// R_a(theta): the right-handed rotation by theta degrees about the unit axis a.
inline Mat3 axis_rotation(const Vec3& a, double theta_deg) {
  return Eigen::AngleAxisd(theta_deg * kDegree, a).toRotationMatrix();
}

// eta = R^T (0, 0, 1).
inline Vec3 position_of_orientation(const Mat3& R) { return R.row(2).transpose(); }

// One axis of a bench: its name in sheets and files, and its travel. A continuous axis turns
// without stops (its angles are read modulo 360 and it travels the short way round); a limited one
// stays within [lo, hi] and travels straight.
struct BenchAxis {
  std::string name;  // "theta1_deg", "tilt_deg"
  double lo = -180, hi = 180;
  bool continuous = true;
};

// How the meter is fixed to the bench: `rotation` takes the meter's frame to the platform's at zero
// angles. Changing it is a remount, done by hand.
struct Mounting {
  std::string label;  // for the sheet: "+z up", "face -z down"
  std::string value;  // for JSON and CSV comments: "upright", "-z", "7"
  Mat3 rotation = Mat3::Identity();
};

// One way to set a bench: a mounting and its axes' angles (degrees); NaN marks an axis whose angle
// does not matter for this position (a pole of a tilt table's azimuth): it stays where it is.
struct BenchSetting {
  int mounting = 0;
  std::vector<double> angles;
};

// The angle in (-180, 180].
inline double wrap_deg(double a) {
  double w = std::remainder(a, 360.0);
  return w <= -180.0 ? w + 360.0 : w;
}

// How far an axis turns from a to b (degrees); 0 when either is free.
inline double axis_travel(const BenchAxis& axis, double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return 0.0;
  return axis.continuous ? std::abs(wrap_deg(b - a)) : std::abs(b - a);
}

// Every way to write the solved angle `a` on the axis: one value in (-180, 180] on a continuous
// axis; on a limited one each a + 360 k within its limits (clamped when within kLimitSlackDeg).
// NaN (free) stays NaN.
inline std::vector<double> axis_values(const BenchAxis& axis, double a) {
  if (std::isnan(a)) return {a};
  if (axis.continuous) return {wrap_deg(a)};
  std::vector<double> out;
  const double w = wrap_deg(a);
  for (int k = -3; k <= 3; ++k) {
    const double v = w + 360.0 * k;
    if (v >= axis.lo - kLimitSlackDeg && v <= axis.hi + kLimitSlackDeg) out.push_back(std::clamp(v, axis.lo, axis.hi));
  }
  return out;
}

// Paden-Kahan subproblem 1: the angle theta (degrees) about the unit axis a with R_a(theta) p = q,
// for unit p, q with a.p = a.q. NaN when p lies on the axis (every angle does).
inline double angle_taking(const Vec3& a, const Vec3& p, const Vec3& q) {
  const Vec3 pp = p - a.dot(p) * a, qq = q - a.dot(q) * a;
  if (pp.norm() < kOnAxisDeg * kDegree) return std::nan("");
  return std::atan2(a.dot(pp.cross(qq)), pp.dot(qq)) / kDegree;
}

// Paden-Kahan subproblem 2 for two gimbal axes: every (theta1, theta2) with
// R_a2(theta2)^T R_a1(theta1)^T v = eta (a1, a2 unit and not parallel; v, eta unit). Both sides equal
// w = R_a1(theta1)^T v, which lies on the circle a1.w = a1.v and on the circle a2.w = a2.eta: w is
// one of their (at most two) intersections. Empty when the circles do not meet.
inline std::vector<std::pair<double, double>> two_axis_angles(const Vec3& a1, const Vec3& a2, const Vec3& v,
                                                              const Vec3& eta) {
  const double c = a1.dot(a2), p = a1.dot(v), q = a2.dot(eta), s2 = 1 - c * c;
  const double alpha = (p - c * q) / s2, beta = (q - c * p) / s2;
  double g2 = (1 - alpha * alpha - beta * beta - 2 * alpha * beta * c) / s2;
  // A position just beyond the reach (within kLimitSlackDeg) is taken on its edge.
  if (g2 < -std::pow(kLimitSlackDeg * kDegree, 2)) return {};
  g2 = std::max(g2, 0.0);
  const Vec3 n = a1.cross(a2);
  std::vector<std::pair<double, double>> out;
  for (const double sign : {1.0, -1.0}) {
    const Vec3 w = (alpha * a1 + beta * a2 + sign * std::sqrt(g2) * n).normalized();
    // R_a1(theta1) w = v and R_a2(theta2) eta = w.
    out.emplace_back(angle_taking(a1, w, v), angle_taking(a2, eta, w));
    if (g2 == 0) break;
  }
  return out;
}

// The rotation taking the meter's frame to the platform's when the meter's `up` axis points up and
// its azimuth frame (region.hpp's azimuth_frame(up): e1, e2) lies along the platform's x and y: rows
// e1, e2, up. So a tilt table's tilt and azimuth are the tilt_deg and azimuth_deg columns that
// `evaluate` writes for a cap about `up`.
Mat3 mounting_rotation(const Vec3& up);

}  // namespace scalcal
