// The fit of a 12-point program to the pentagonal 4-designs (pentagonal_match.hpp).
#include "numeric/certify/pentagonal_match.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace scalcal::certify_detail {

namespace {

constexpr double kTolerance = 1e-4;

// A family member in the frame (e1, e2, axis): point 0 and 1 the poles, then ring j = 0, 1 at
// height +-1/sqrt 5 with angles t_j + 72 k degrees. The fit keeps, for each, its position index.
struct Fit {
  Eigen::Matrix3d frame;         // columns e1, e2, axis
  std::array<double, 2> turn{};  // t_0, t_1
  std::array<int, 12> position{};
};

// The member with poles at positions north and south (antipodal within the tolerance), if any.
std::optional<Fit> fit(const std::vector<Eigen::Vector3d>& p, int north, int south) {
  const double h = 1 / std::sqrt(5.0);
  Fit f;
  f.position.fill(-1);
  const Eigen::Vector3d axis = (p[north] - p[south]).normalized();
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  f.frame << e1, e2, axis;
  f.position[0] = north;
  f.position[1] = south;
  std::array<std::vector<std::pair<double, int>>, 2> ring;  // (angle, position)
  for (int i = 0; i < 12; ++i) {
    if (i == north || i == south) continue;
    const double z = p[i].dot(axis);
    if (std::abs(std::abs(z) - h) > kTolerance) return std::nullopt;
    ring[z > 0 ? 0 : 1].push_back({std::atan2(p[i].dot(e2), p[i].dot(e1)), i});
  }
  const double step = 2 * std::numbers::pi / 5;
  for (int j = 0; j < 2; ++j) {
    if (ring[j].size() != 5) return std::nullopt;
    // The turn: the circular mean of each angle's offset from the nearest multiple of 72 degrees.
    double c = 0, s = 0;
    for (const auto& [angle, i] : ring[j]) c += std::cos(5 * angle), s += std::sin(5 * angle);
    f.turn[j] = std::atan2(s, c) / 5;
    for (const auto& [angle, i] : ring[j]) {
      const int k = static_cast<int>(std::lround((angle - f.turn[j]) / step) % 5 + 5) % 5;
      int& slot = f.position[2 + 5 * j + k];
      if (slot >= 0) return std::nullopt;  // two positions on one vertex
      slot = i;
    }
  }
  return f;
}

}  // namespace

std::optional<std::vector<IPoint>> pentagonal_design_near(const Program& program) {
  if (program.size() != 12) return std::nullopt;
  std::vector<Eigen::Vector3d> p;
  for (const auto& e : program.positions) p.push_back(e.normalized());
  // Any antipodal pair may be the poles (in the icosahedron every one is); the first that fits is used.
  std::optional<Fit> f;
  for (int i = 0; i < 12 && !f; ++i)
    for (int j = i + 1; j < 12 && !f; ++j)
      if ((p[i] + p[j]).norm() < kTolerance) f = fit(p, i, j);
  if (!f) return std::nullopt;

  // Exact rotation from the quaternion q (its double coefficients taken as exact): R(q)/|q|^2 is
  // orthogonal with determinant 1 for any q != 0. The turns enter through tau = tan(t/2), with
  // cos t = (1 - tau^2)/(1 + tau^2), sin t = 2 tau/(1 + tau^2), exactly on the circle.
  const Eigen::Quaterniond qd(f->frame);
  const Interval w(qd.w()), x(qd.x()), y(qd.y()), z(qd.z());
  const Interval n = w * w + x * x + y * y + z * z, two(2);
  const Interval R[3][3] = {{w * w + x * x - y * y - z * z, two * (x * y - w * z), two * (x * z + w * y)},
                            {two * (x * y + w * z), w * w - x * x + y * y - z * z, two * (y * z - w * x)},
                            {two * (x * z - w * y), two * (y * z + w * x), w * w - x * x - y * y + z * z}};
  const Interval s5 = sqrt(Interval(5)), h = Interval(1) / s5, r = two / s5;
  // cos and sin of 72 k degrees: cos 72 = (sqrt 5 - 1)/4, sin 72 = sqrt(10 + 2 sqrt 5)/4, by the double angle.
  const Interval c72 = (s5 - Interval(1)) / Interval(4), s72 = sqrt(Interval(10) + two * s5) / Interval(4);
  std::array<Interval, 5> ck, sk;
  ck[0] = Interval(1), sk[0] = Interval(0);
  for (int k = 1; k < 5; ++k) ck[k] = ck[k - 1] * c72 - sk[k - 1] * s72, sk[k] = sk[k - 1] * c72 + ck[k - 1] * s72;

  std::array<std::array<Interval, 3>, 12> local;  // the member in the frame
  local[0] = {Interval(0), Interval(0), Interval(1)};
  local[1] = {Interval(0), Interval(0), Interval(-1)};
  for (int j = 0; j < 2; ++j) {
    const Interval tau(std::tan(f->turn[j] / 2));
    const Interval ct = (Interval(1) - tau * tau) / (Interval(1) + tau * tau),
                   st = two * tau / (Interval(1) + tau * tau);
    for (int k = 0; k < 5; ++k)
      local[2 + 5 * j + k] = {r * (ct * ck[k] - st * sk[k]), r * (st * ck[k] + ct * sk[k]), j == 0 ? h : Interval(-h)};
  }
  std::vector<IPoint> exact(12);
  for (int slot = 0; slot < 12; ++slot)
    for (int a = 0; a < 3; ++a)
      exact[f->position[slot]][a] =
          (R[a][0] * local[slot][0] + R[a][1] * local[slot][1] + R[a][2] * local[slot][2]) / n;
  return exact;
}

}  // namespace scalcal::certify_detail
