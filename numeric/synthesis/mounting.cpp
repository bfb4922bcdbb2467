// The best mounting of a meter in a jig, by Nelder-Mead over rotations (mounting.hpp).
#include "numeric/synthesis/mounting.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Geometry>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/synthesis/seeds.hpp"

namespace scalcal {

Program mounted(const Eigen::Matrix3d& orientation, const Program& normals) {
  Program p;
  p.positions.reserve(normals.positions.size());
  for (const auto& n : normals.positions) p.positions.push_back(orientation * n);
  return p;
}

Eigen::Matrix3d uniform_rotation(double u1, double u2, double u3) {
  const double two_pi = 2 * M_PI, a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const Eigen::Quaterniond q(b * std::cos(two_pi * u3), a * std::sin(two_pi * u2), a * std::cos(two_pi * u2),
                             b * std::sin(two_pi * u3));
  return q.normalized().toRotationMatrix();
}

namespace {

using Vec = Eigen::Vector3d;

// O(w) = exp([w]x) O0: a chart of the rotations near O0 with no singularity at w = 0.
Eigen::Matrix3d moved(const Eigen::Matrix3d& O0, const Vec& w) {
  const double angle = w.norm();
  if (angle == 0) return O0;
  return Eigen::AngleAxisd(angle, w / angle).toRotationMatrix() * O0;
}

struct Local {
  Eigen::Matrix3d orientation;
  double value;
};

// Nelder-Mead (Lagarias et al. 1998 coefficients) on w, restarted about its best vertex until a
// restart no longer improves: a collapsed simplex is the method's known failure on a kinked max.
Local nelder_mead(const std::function<double(const Eigen::Matrix3d&)>& f, Eigen::Matrix3d O, double step) {
  double best = f(O);
  for (int restart = 0; restart < 8; ++restart) {
    std::array<Vec, 4> x;
    std::array<double, 4> fx;
    x[0] = Vec::Zero();
    fx[0] = best;
    for (int i = 0; i < 3; ++i) {
      x[i + 1] = Vec::Zero();
      x[i + 1](i) = step;
      fx[i + 1] = f(moved(O, x[i + 1]));
    }
    auto value = [&](const Vec& w) { return f(moved(O, w)); };
    for (int it = 0; it < 600; ++it) {
      std::array<int, 4> order{0, 1, 2, 3};
      std::sort(order.begin(), order.end(), [&](int a, int b) { return fx[a] < fx[b]; });
      const int lo = order[0], hi = order[3], second = order[2];
      double size = 0;
      for (int i = 0; i < 4; ++i) size = std::max(size, (x[i] - x[lo]).norm());
      if (size < 1e-11 || !(fx[hi] - fx[lo] > 1e-15 * std::abs(fx[lo]))) break;
      Vec centroid = Vec::Zero();
      for (int i = 0; i < 4; ++i)
        if (i != hi) centroid += x[i] / 3;
      const Vec xr = centroid + (centroid - x[hi]);
      const double fr = value(xr);
      if (fr < fx[lo]) {
        const Vec xe = centroid + 2 * (centroid - x[hi]);
        const double fe = value(xe);
        if (fe < fr)
          x[hi] = xe, fx[hi] = fe;
        else
          x[hi] = xr, fx[hi] = fr;
      } else if (fr < fx[second]) {
        x[hi] = xr, fx[hi] = fr;
      } else {
        const bool outside = fr < fx[hi];
        const Vec xc = outside ? centroid + 0.5 * (xr - centroid) : centroid + 0.5 * (x[hi] - centroid);
        const double fc = value(xc);
        if (fc < (outside ? fr : fx[hi])) {
          x[hi] = xc, fx[hi] = fc;
        } else {
          for (int i = 0; i < 4; ++i)
            if (i != lo) x[i] = x[lo] + 0.5 * (x[i] - x[lo]), fx[i] = value(x[i]);
        }
      }
    }
    const int lo = static_cast<int>(std::min_element(fx.begin(), fx.end()) - fx.begin());
    const bool improved = fx[lo] < best * (1 - 1e-13);
    if (fx[lo] < best) {
      best = fx[lo];
      O = moved(O, x[lo]);
    }
    if (!improved) break;
    step = std::max(step * 0.1, 1e-6);
  }
  return {O, best};
}

}  // namespace

MountingResult best_mounting(const Program& normals, const MountingOptions& options) {
  if (normals.positions.empty()) throw std::invalid_argument("best_mounting: the jig has no faces");
  if (options.starts < 1) throw std::invalid_argument("best_mounting: at least one start is needed");
  const auto f = [&](const Eigen::Matrix3d& O) {
    const double v = criterion_value(mounted(O, normals), options.criterion);
    return std::isfinite(v) ? v : std::numeric_limits<double>::infinity();
  };
  MountingResult out;
  out.value_default = f(Eigen::Matrix3d::Identity());
  std::vector<Local> ends;
  for (int k = 0; k < options.starts; ++k) {
    Eigen::Matrix3d O0 = Eigen::Matrix3d::Identity();
    if (k > 0) {
      std::uint64_t s = start_seed(options.seed, static_cast<std::uint64_t>(k));
      double u[3];
      for (double& x : u) {
        s = splitmix64(s);
        x = static_cast<double>(s >> 11) * 0x1.0p-53;
      }
      O0 = uniform_rotation(u[0], u[1], u[2]);
    }
    ends.push_back(nelder_mead(f, O0, 0.3));
    if (options.progress) options.progress(k + 1, options.starts);
  }
  // The first start within kHitTolerance of the lowest value: equivalent mountings (the jig's and the
  // program's symmetries) reach one value to the last bits, which must not choose between them.
  double lowest = ends[0].value;
  for (const auto& e : ends) lowest = std::min(lowest, e.value);
  std::size_t best = 0;
  while (best + 1 < ends.size() && !(ends[best].value <= lowest + kHitTolerance * std::abs(lowest))) ++best;
  out.orientation = ends[best].orientation;
  out.value = ends[best].value;
  out.starts = options.starts;
  for (const auto& e : ends)
    if (e.value <= out.value * (1 + kHitTolerance)) {
      ++out.hits;
      out.spread = std::max(out.spread, (e.value - out.value) / out.value);
    }
  return out;
}

}  // namespace scalcal
