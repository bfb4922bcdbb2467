// The fit of d3_match.hpp: poles, four rings of three, the turn about the axis; then the exact
// design in MPFI from its closed form (proofs/checks/d3_design.cpp), rotated exactly.
#include "numeric/certify/d3_match.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace scalcal::certify_detail {

namespace {

constexpr double kTolerance = 1e-4;
constexpr double kStep = 2 * std::numbers::pi / 3;

// The closed form (proof.d3_design), for one choice of the signs of C1 and S1.
template <class T>
struct Closed {
  T z[2], r[2], c3[2], s3[2];  // heights, ring radii, cos 3 phi, sin 3 phi of the two orbits

  Closed(int sign_c, int sign_s) {
    using std::sqrt;
    const T s35 = sqrt(T(35));
    z[0] = sqrt((T(10) + s35) / T(45));
    z[1] = sqrt((T(10) - s35) / T(45));
    for (int k = 0; k < 2; ++k) r[k] = sqrt(T(1) - z[k] * z[k]);
    const T t = T(7261) / T(9826) - T(1431) * s35 / T(68782);
    c3[0] = T(sign_c) * sqrt(T(1) - t);
    s3[0] = T(sign_s) * sqrt(t);
    const T a = r[0] * r[0] * r[0], b = r[1] * r[1] * r[1];
    c3[1] = -(a / b) * c3[0];
    s3[1] = -(z[0] * a) / (z[1] * b) * s3[0];
  }
};

// Ring j: 0, 1 the orbit of p1 at heights +z1, -z1 (angles +phi1, -phi1), 2, 3 that of p2.
struct Ring {
  int orbit;
  int sign;  // +1: height +z, angles phi + 120 k; -1: height -z, angles -phi + 120 k
};
constexpr std::array<Ring, 4> kRings = {{{0, 1}, {0, -1}, {1, 1}, {1, -1}}};

struct Fit {
  Eigen::Matrix3d frame;  // columns e1, e2, axis
  int sign_c = 1, sign_s = 1;
  double turn = 0;                 // psi: the design is turned by psi about the axis
  std::array<int, 14> position{};  // slot -> position: 0, 1 the poles, then ring j point k at 2 + 3 j + k
};

// The fit with the poles at positions north and south, if one sign choice matches every point.
std::optional<Fit> fit(const std::vector<Eigen::Vector3d>& p, int north, int south) {
  Fit f;
  const Eigen::Vector3d axis = (p[north] - p[south]).normalized();
  const Eigen::Vector3d e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
  f.frame << e1, e2, axis;
  std::array<std::vector<std::pair<double, int>>, 4> ring;  // (angle, position)
  for (int sign_c : {1, -1})
    for (int sign_s : {1, -1}) {
      const Closed<double> d(sign_c, sign_s);
      for (auto& r : ring) r.clear();
      bool heights = true;
      for (int i = 0; i < 14 && heights; ++i) {
        if (i == north || i == south) continue;
        const double z = p[i].dot(axis);
        int j = std::abs(std::abs(z) - d.z[0]) < kTolerance ? 0 : std::abs(std::abs(z) - d.z[1]) < kTolerance ? 2 : -1;
        heights = j >= 0;
        if (heights) ring[j + (z < 0)].push_back({std::atan2(p[i].dot(e2), p[i].dot(e1)), i});
      }
      if (!heights) return std::nullopt;
      for (const auto& r : ring)
        if (r.size() != 3) return std::nullopt;
      // The turn psi: the circular mean of 3 (angle - base) over the twelve ring points.
      double c = 0, s = 0;
      for (int j = 0; j < 4; ++j) {
        const double base = kRings[j].sign * std::atan2(d.s3[kRings[j].orbit], d.c3[kRings[j].orbit]) / 3;
        for (const auto& [angle, i] : ring[j]) c += std::cos(3 * (angle - base)), s += std::sin(3 * (angle - base));
      }
      f.turn = std::atan2(s, c) / 3;
      f.position.fill(-1);
      f.position[0] = north;
      f.position[1] = south;
      bool matched = true;
      for (int j = 0; j < 4 && matched; ++j) {
        const Ring& rg = kRings[j];
        const double base = rg.sign * std::atan2(d.s3[rg.orbit], d.c3[rg.orbit]) / 3 + f.turn;
        for (const auto& [angle, i] : ring[j]) {
          const double steps = (angle - base) / kStep;
          const long k = std::lround(steps);
          int& slot = f.position[2 + 3 * j + static_cast<int>(((k % 3) + 3) % 3)];
          matched = matched && d.r[rg.orbit] * std::abs(steps - k) * kStep < kTolerance && slot < 0;
          slot = i;
        }
      }
      if (matched) {
        f.sign_c = sign_c;
        f.sign_s = sign_s;
        return f;
      }
    }
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<IPoint>> d3_design_near(const Program& program) {
  if (program.size() != 14) return std::nullopt;
  std::vector<Eigen::Vector3d> p;
  for (const auto& e : program.positions) p.push_back(e.normalized());
  std::optional<Fit> f;
  for (int i = 0; i < 14 && !f; ++i)
    for (int j = 0; j < 14 && !f; ++j)
      if (i != j && (p[i] + p[j]).norm() < kTolerance) f = fit(p, i, j);
  if (!f) return std::nullopt;

  // Exact rotation R(q)/|q|^2 from the frame's double quaternion, the turn through tau = tan(psi/2)
  // (exactly on the circle), the design's closed form in MPFI.
  const Eigen::Quaterniond qd(f->frame);
  const Interval w(qd.w()), x(qd.x()), y(qd.y()), z(qd.z()), two(2), one(1);
  const Interval n = w * w + x * x + y * y + z * z;
  const Interval R[3][3] = {{w * w + x * x - y * y - z * z, two * (x * y - w * z), two * (x * z + w * y)},
                            {two * (x * y + w * z), w * w - x * x + y * y - z * z, two * (y * z - w * x)},
                            {two * (x * z - w * y), two * (y * z + w * x), w * w - x * x - y * y + z * z}};
  const Interval tau(std::tan(f->turn / 2));
  const Interval c_turn = (one - tau * tau) / (one + tau * tau), s_turn = two * tau / (one + tau * tau);
  const Closed<Interval> d(f->sign_c, f->sign_s);
  const Interval step = two * acos(Interval(-1)) / Interval(3);  // 120 degrees, enclosed
  std::array<IPoint, 14> local;
  local[0] = {Interval(0), Interval(0), one};
  local[1] = {Interval(0), Interval(0), Interval(-1)};
  for (int j = 0; j < 4; ++j) {
    const Ring& rg = kRings[j];
    const Interval phi = Interval(rg.sign) * atan2(d.s3[rg.orbit], d.c3[rg.orbit]) / Interval(3);
    for (int k = 0; k < 3; ++k) {
      const Interval beta = phi + Interval(k) * step, cb = cos(beta), sb = sin(beta);
      const Interval r = d.r[rg.orbit];
      local[2 + 3 * j + k] = {r * (c_turn * cb - s_turn * sb), r * (s_turn * cb + c_turn * sb),
                              Interval(rg.sign) * d.z[rg.orbit]};
    }
  }
  std::vector<IPoint> exact(14);
  for (int slot = 0; slot < 14; ++slot)
    for (int a = 0; a < 3; ++a)
      exact[f->position[slot]][a] =
          (R[a][0] * local[slot][0] + R[a][1] * local[slot][1] + R[a][2] * local[slot][2]) / n;
  return exact;
}

}  // namespace scalcal::certify_detail
