// The pieces of a tumbling log's calibration (tumbling.hpp).
#include "numeric/calibration/tumbling.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

namespace scalcal {
namespace {

double robust_scale(const std::vector<double>& r) {
  std::vector<double> a;
  a.reserve(r.size());
  for (double x : r) a.push_back(std::abs(x));
  const auto k = a.size() / 2;
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(k), a.end());
  return 1.4826 * a[k];
}

template <class Model>
std::vector<Eigen::VectorXd> rows_of(const std::vector<Vec3>& directions) {
  std::vector<Eigen::VectorXd> out;
  out.reserve(directions.size());
  for (const auto& u : directions) out.emplace_back(Model::row(u));
  return out;
}

}  // namespace

std::vector<PositionSamples> sample_positions(const RawLog& log, const std::vector<char>& use,
                                              std::vector<int>& sample_index) {
  std::vector<PositionSamples> out;
  sample_index.clear();
  for (int i = 0; i < log.size(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!use[k]) continue;
    PositionSamples p;
    p.samples.push_back(log.samples[k]);
    p.line = log.lines[k];
    p.sample_lines.push_back(log.lines[k]);
    out.push_back(std::move(p));
    sample_index.push_back(i);
  }
  return out;
}

std::vector<DisturbedStretch> disturbed_stretches(const RawLog& log, const std::vector<int>& sample_index,
                                                  const std::vector<double>& residual, int gap) {
  std::vector<DisturbedStretch> out;
  if (residual.empty()) return out;
  const double scale = robust_scale(residual);
  if (!(scale > 0)) return out;
  const auto n = residual.size();
  const auto beyond = [&](std::size_t k, double scales) { return std::abs(residual[k]) > scales * scale; };
  std::size_t k = 0;
  while (k < n) {
    if (!beyond(k, kDisturbedScales)) {
      ++k;
      continue;
    }
    // Grow back and forth over neighbours beyond half the cut, then across short quiet gaps.
    std::size_t a = k, b = k;
    while (a > 0 && beyond(a - 1, kDisturbedScales / 2)) --a;
    for (std::size_t c = b + 1; c < n && c <= b + static_cast<std::size_t>(gap); ++c)
      if (beyond(c, kDisturbedScales / 2)) b = c;
    DisturbedStretch s;
    s.begin = sample_index[a];
    s.end = sample_index[b];
    s.start = log.t[static_cast<std::size_t>(s.begin)];
    s.stop = log.t[static_cast<std::size_t>(s.end)];
    s.first_line = log.lines[static_cast<std::size_t>(s.begin)];
    s.last_line = log.lines[static_cast<std::size_t>(s.end)];
    for (std::size_t c = a; c <= b; ++c) s.worst = std::max(s.worst, std::abs(residual[c]));
    if (!out.empty() && s.begin - out.back().end <= gap) {
      out.back().end = s.end;
      out.back().stop = s.stop;
      out.back().last_line = s.last_line;
      out.back().worst = std::max(out.back().worst, s.worst);
    } else {
      out.push_back(s);
    }
    k = b + 1;
  }
  return out;
}

std::vector<Eigen::VectorXd> model_rows(ModelKind model, const std::vector<Vec3>& directions) {
  return visit_model(model, [&](auto m) { return rows_of<decltype(m)>(directions); });
}

Eigen::MatrixXd newey_west_covariance(const std::vector<Eigen::VectorXd>& rows, const std::vector<double>& residual,
                                      int lag) {
  const auto n = rows.size();
  const Eigen::Index P = rows.empty() ? 0 : rows[0].size();
  Eigen::MatrixXd info = Eigen::MatrixXd::Zero(P, P), S = Eigen::MatrixXd::Zero(P, P);
  std::vector<Eigen::VectorXd> g(n);
  for (std::size_t t = 0; t < n; ++t) {
    info += rows[t] * rows[t].transpose();
    g[t] = rows[t] * residual[t];
    S += g[t] * g[t].transpose();
  }
  for (int l = 1; l <= lag && static_cast<std::size_t>(l) < n; ++l) {
    const double w = 1 - static_cast<double>(l) / (lag + 1);
    Eigen::MatrixXd Gl = Eigen::MatrixXd::Zero(P, P);
    for (std::size_t t = 0; t + static_cast<std::size_t>(l) < n; ++t)
      Gl += g[t] * g[t + static_cast<std::size_t>(l)].transpose();
    S += w * (Gl + Gl.transpose());
  }
  const Eigen::MatrixXd K = info.ldlt().solve(Eigen::MatrixXd::Identity(P, P));
  const double small_sample = n > static_cast<std::size_t>(P) ? static_cast<double>(n) / (n - P) : 1;
  return small_sample * K * S * K;
}

namespace {

double median_turn(const std::vector<Vec3>& u, std::size_t lag) {
  std::vector<double> cosines;
  cosines.reserve(u.size() - lag);
  for (std::size_t t = 0; t + lag < u.size(); ++t) cosines.push_back(u[t].dot(u[t + lag]));
  const auto mid = cosines.begin() + static_cast<std::ptrdiff_t>(cosines.size() / 2);
  std::nth_element(cosines.begin(), mid, cosines.end());
  return std::acos(std::clamp(*mid, -1.0, 1.0));
}

}  // namespace

int decorrelation_lag(const std::vector<Vec3>& directions) {
  const std::size_t most = std::max<std::size_t>(1, directions.size() / 4);
  if (directions.size() < 8) return static_cast<int>(most);
  std::size_t lo = 0, hi = 1;
  while (hi < most && median_turn(directions, hi) < kDecorrelationAngle) lo = hi, hi *= 2;
  if (hi >= most)
    return median_turn(directions, most) < kDecorrelationAngle ? static_cast<int>(most)
                                                               : static_cast<int>(hi > most ? most : hi);
  while (hi - lo > 1) {  // median_turn(lo) < angle <= median_turn(hi)
    const std::size_t mid = lo + (hi - lo) / 2;
    (median_turn(directions, mid) < kDecorrelationAngle ? lo : hi) = mid;
  }
  return static_cast<int>(hi);
}

std::vector<Vec3> fibonacci_sphere(int n) {
  std::vector<Vec3> out;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1 - (2 * i + 1.0) / n, r = std::sqrt(1 - z * z), a = golden * i;
    out.emplace_back(r * std::cos(a), r * std::sin(a), z);
  }
  return out;
}

Coverage sphere_coverage(const std::vector<Vec3>& directions) {
  Coverage c;
  // Distinct directions at about 2 degrees (a 10000-cell lattice), so the search costs the same for a
  // long log as for a short one.
  const std::vector<Vec3> fine = fibonacci_sphere(10000);
  const std::vector<Vec3> cells = fibonacci_sphere(100);
  const auto nearest = [](const std::vector<Vec3>& points, const Vec3& u) {
    std::size_t best = 0;
    double d = -2;
    for (std::size_t k = 0; k < points.size(); ++k)
      if (const double x = points[k].dot(u); x > d) d = x, best = k;
    return best;
  };
  std::vector<char> fine_hit(fine.size(), 0), cell_hit(cells.size(), 0);
  // Bucketed by z for the fine lattice's nearest point: its points are sorted by z.
  for (const auto& u : directions) {
    if (!u.allFinite()) continue;
    const double z = std::clamp(u.z(), -1.0, 1.0);
    const int centre = static_cast<int>(std::lround((1 - z) * 10000 / 2 - 0.5));
    std::size_t best = 0;
    double d = -2;
    for (int k = std::max(0, centre - 400); k < std::min(10000, centre + 400); ++k)
      if (const double x = fine[static_cast<std::size_t>(k)].dot(u); x > d) d = x, best = static_cast<std::size_t>(k);
    fine_hit[best] = 1;
    cell_hit[nearest(cells, u)] = 1;
  }
  std::vector<Vec3> hit;
  for (std::size_t k = 0; k < fine.size(); ++k)
    if (fine_hit[k]) hit.push_back(fine[k]);
  c.covered_share = static_cast<double>(std::count(cell_hit.begin(), cell_hit.end(), 1)) / cells.size();
  if (hit.empty()) return c;
  double worst = 1;
  for (const auto& centre : fibonacci_sphere(2000)) {
    double closest = -1;
    for (const auto& h : hit) closest = std::max(closest, centre.dot(h));
    if (closest < worst) worst = closest, c.gap_centre = centre;
  }
  c.largest_gap_deg = std::acos(std::clamp(worst, -1.0, 1.0)) * 180 / M_PI;
  return c;
}

}  // namespace scalcal
