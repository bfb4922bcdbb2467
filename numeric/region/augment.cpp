#include "numeric/region/augment.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "numeric/criteria/evaluation.hpp"

namespace scalcal {
namespace {

using Model = Paper9Model;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The criterion of M at n positions, or infinity when M is singular (the greedy step must still
// rank candidates for a rank-deficient start: a tiny ridge orders them by what they make identifiable).
template <class Crit>
double value_of(const Mat9& M, double n) {
  Eigen::LLT<Mat9> llt(M);
  if (llt.info() != Eigen::Success) return kInfinity;
  const Mat9 K = llt.solve(Mat9::Identity());
  const Vec9 eigenvalues = Eigen::SelfAdjointEigenSolver<Mat9>(K, Eigen::EigenvaluesOnly).eigenvalues();
  if (!(eigenvalues.minCoeff() > 0)) return kInfinity;
  return Crit::template value<Model>(InverseInformation<double, 9>{K, eigenvalues}, n);
}

template <class Crit>
double ranked_value(const Mat9& M, double n) {
  const double v = value_of<Crit>(M, n);
  if (std::isfinite(v)) return v;
  // Below rank 9 every candidate gives infinity: rank by the criterion with a ridge far below any
  // real information, so that a candidate that raises the rank wins by orders of magnitude.
  return 1e300 * std::min(1.0, value_of<Crit>(M + 1e-9 * Mat9::Identity(), n) * 1e-300);
}

// Moves x within the region along great circles while the criterion improves: steps of 2 degrees
// down to 1e-4 degrees in the eight directions of the tangent plane.
template <class Crit>
Vec3 settle(Vec3 x, const Mat9& others, double n, const Region& region) {
  const auto value_at = [&](const Vec3& y) { const Vec9 h = Model::row(y); return ranked_value<Crit>(others + h * h.transpose(), n); };
  double best = value_at(x);
  for (double step = 2.0 * M_PI / 180; step > 1e-4 * M_PI / 180; step *= 0.5) {
    bool moved = true;
    while (moved) {
      moved = false;
      const Vec3 helper = std::abs(x.z()) < 0.9 ? Vec3(0, 0, 1) : Vec3(1, 0, 0);
      const Vec3 e1 = helper.cross(x).normalized(), e2 = x.cross(e1);
      for (int k = 0; k < 8; ++k) {
        const double a = k * M_PI / 4;
        const Vec3 y = (std::cos(step) * x + std::sin(step) * (std::cos(a) * e1 + std::sin(a) * e2)).normalized();
        if (!region.contains(y, 0.0)) continue;
        const double v = value_at(y);
        if (v < best) {
          best = v;
          x = y;
          moved = true;
          break;
        }
      }
    }
  }
  return x;
}

template <class Crit>
AugmentedProgram augment_with(const Program& given, int add, const Region& region) {
  AugmentedProgram out;
  out.program = given;
  Mat9 M = Mat9::Zero();
  for (const Vec3& p : given.positions) {
    const Vec9 h = Model::row(p);
    M += h * h.transpose();
  }
  out.value_before = value_of<Crit>(M, given.size());
  const std::vector<Vec3> candidates = region.grid(2.0);
  const auto best_addition = [&](const Mat9& base, double n) {
    double best = kInfinity;
    Vec3 chosen = candidates.front();
    for (const Vec3& x : candidates) {
      const Vec9 h = Model::row(x);
      const double v = ranked_value<Crit>(base + h * h.transpose(), n);
      if (v < best) {
        best = v;
        chosen = x;
      }
    }
    return region.zones.empty() ? chosen : settle<Crit>(chosen, base, n, region);  // moves stay inside
  };
  const auto information = [](const std::vector<Vec3>& xs) {
    Mat9 out = Mat9::Zero();
    for (const Vec3& x : xs) {
      const Vec9 h = Model::row(x);
      out += h * h.transpose();
    }
    return out;
  };
  const double n = given.size() + add;
  for (int k = 0; k < add; ++k) {
    out.added.push_back(best_addition(M + information(out.added), given.size() + k + 1));
  }
  // Greedy choices are myopic: exchange each added position for the best one given all the others
  // (Fedorov's exchange restricted to the added positions) until a full pass changes nothing.
  double current = ranked_value<Crit>(M + information(out.added), n);
  for (int pass = 0; pass < 20; ++pass) {
    bool changed = false;
    for (std::size_t k = 0; k < out.added.size(); ++k) {
      std::vector<Vec3> others = out.added;
      others.erase(others.begin() + static_cast<std::ptrdiff_t>(k));
      const Vec3 x = best_addition(M + information(others), n);
      others.insert(others.begin() + static_cast<std::ptrdiff_t>(k), x);
      const double v = ranked_value<Crit>(M + information(others), n);
      if (v < current * (1 - 1e-12)) {
        out.added = others;
        current = v;
        changed = true;
      }
    }
    if (!changed) break;
  }
  M += information(out.added);
  out.program.positions.insert(out.program.positions.end(), out.added.begin(), out.added.end());
  out.value = value_of<Crit>(M, out.program.size());
  return out;
}

}  // namespace

AugmentedProgram augment_program(const Program& given, int add, CriterionKind criterion, const Region& region) {
  return visit_criterion(criterion, [&](auto C) { return augment_with<decltype(C)>(given, add, region); });
}

}  // namespace scalcal
