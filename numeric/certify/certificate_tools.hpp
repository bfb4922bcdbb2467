// The small pieces every certificate of numeric/certify shares: the rotation gauge, Newton's
// acceptance test, interval Cholesky and Finsler's test, outward printing of enclosures, and the
// distance, in a program's own chart, from that program to an enclosed exact program.
#pragma once
#include <algorithm>
#include <array>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "numeric/certify/interval.hpp"
#include "numeric/certify/krawczyk.hpp"
#include "numeric/certify/sphere_chart.hpp"

namespace scalcal::certify_detail {

inline std::string sci(const Real& x, int digits = 3) {
  std::ostringstream s;
  s << std::scientific << std::setprecision(digits - 1) << static_cast<double>(x);
  return s.str();
}

// For an O(3)-invariant criterion (D) rotations leave the value alone: u, v of position 0 and u of
// the position farthest from its axis are held (SphereChart::of aims that u along e0 x e_second).
struct Gauge {
  SphereChart chart;
  std::vector<int> held;  // full chart indices held at 0
};

inline Gauge gauge_for(const Program& p, bool rotations) {
  if (!rotations) return {SphereChart::of(p), {}};
  int second = 1;
  double far = -1;
  for (int j = 1; j < p.size(); ++j) {
    const double s = p.positions[0].normalized().cross(p.positions[j].normalized()).norm();
    if (s > far) far = s, second = j;
  }
  return {SphereChart::of(p, 0, second), {0, 1, 2 * second}};
}

// Newton's stopping residual at `digits` working digits.
inline Real newton_tolerance(int digits) { return pow(Real(10), -Real(digits - 8)); }

// Why a Newton run does not count as converged near the program (empty when it does).
inline std::string newton_failure(const NewtonOutcome& n, const Real& moved, double max_move, int digits) {
  if (n.residual <= pow(Real(10), -Real(digits / 2)) && moved <= max_move) return "";
  return "did not converge near the program (residual " + sci(n.residual) + ", moved " + sci(moved) + ")";
}

// Cholesky over an interval matrix: true when every matrix in it is positive definite.
inline bool positive_definite(IMatX H) {
  const Eigen::Index m = H.rows();
  for (Eigen::Index k = 0; k < m; ++k) {
    for (Eigen::Index j = 0; j < k; ++j) H(k, k) -= H(k, j) * H(k, j);
    if (!(lo(H(k, k)) > 0)) return false;
    H(k, k) = sqrt(H(k, k));
    for (Eigen::Index i = k + 1; i < m; ++i) {
      for (Eigen::Index j = 0; j < k; ++j) H(i, k) -= H(i, j) * H(k, j);
      H(i, k) /= H(k, k);
    }
  }
  return true;
}

// Finsler's lemma over a box: H + rho G^T G positive definite for one rho in 1, 10, ..., 1e8 proves
// H positive definite on the kernel of G (the second-order sufficient condition of a KKT point).
inline bool positive_on_kernel(const IMatX& H, const IMatX& GtG) {
  for (double rho = 1; rho <= 1e8; rho *= 10)
    if (positive_definite(IMatX(H + Interval(rho) * GtG))) return true;
  return false;
}

// An enclosure bound printed rounded outward: widening by one unit of the last printed digit
// covers the decimal rounding of the conversion.
inline std::string outward(const Real& x, int digits, bool up) {
  using std::floor;
  using std::log10;
  const Real e = floor(log10(abs(x)));
  const Real unit = pow(Real(10), e - Real(digits - 1));
  return (up ? Real(x + unit) : Real(x - unit)).str(digits, std::ios::scientific);
}

using IPoint = std::array<Interval, 3>;

// The enclosed positions eta_i(U_i, V_i) of a chart over a box of full chart coordinates.
inline std::vector<IPoint> enclosed_positions(const SphereChart& chart, const IVecX& full) {
  std::vector<IPoint> out;
  for (int i = 0; i < static_cast<int>(chart.e.size()); ++i) {
    const auto e = chart.position<Interval>(i, full(2 * i), full(2 * i + 1));
    out.push_back({e[0].f, e[1].f, e[2].f});
  }
  return out;
}

// The inf-norm of the chart coordinates, in `chart` (built on the given program), of exact positions
// enclosed in `target` (one per position): eta(u, v) = t iff e + u t1 + v t2 = s t with s > 0, so by
// Cramer's rule, the determinant cancelling, u = (t2 x e).t / (t1 x t2).t and v = (e x t1).t / (t1 x t2).t.
// nullopt when a target is not proven to lie in the open hemisphere about its position.
inline std::optional<Real> chart_radius(const SphereChart& chart, const std::vector<IPoint>& target) {
  Real radius(0);
  for (std::size_t i = 0; i < target.size(); ++i) {
    const IPoint& t = target[i];
    auto triple = [&t](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      Interval acc(0);
      for (int k = 0; k < 3; ++k) {
        const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        acc += (Interval(a(k1)) * Interval(b(k2)) - Interval(a(k2)) * Interval(b(k1))) * t[k];
      }
      return acc;
    };
    const Interval along_e = triple(chart.t1[i], chart.t2[i]);
    if (!(lo(along_e) > 0)) return std::nullopt;
    const Interval u = triple(chart.t2[i], chart.e[i]) / along_e, v = triple(chart.e[i], chart.t1[i]) / along_e;
    radius = std::max({radius, mag(u), mag(v)});
  }
  return radius;
}

}  // namespace scalcal::certify_detail
