// Optimal designs on [-1, 1] for polynomial regression (interval_design.hpp).
#include "numeric/thermal/interval_design.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "numeric/thermal/information_criteria.hpp"

namespace scalcal {
namespace {

Eigen::VectorXd powers(int degree, double t) {
  Eigen::VectorXd f(degree + 1);
  f(0) = 1;
  for (int j = 1; j <= degree; ++j) f(j) = f(j - 1) * t;
  return f;
}

// Roots of P_k' in (-1, 1) by Newton's method from the Chebyshev-Lobatto points (P_k and its
// derivatives by the three-term recurrence); they interlace with those guesses closely enough for k <= 6.
std::vector<double> lobatto_points(int k) {
  std::vector<double> out{-1.0};
  for (int i = k - 1; i >= 1; --i) {
    double t = std::cos(M_PI * i / k);
    for (int it = 0; it < 100; ++it) {
      // P_n, P_n' and P_n'' at t, by the recurrence and the Legendre equation.
      double p0 = 1, p1 = t;
      for (int n = 2; n <= k; ++n) {
        const double p2 = ((2 * n - 1) * t * p1 - (n - 1) * p0) / n;
        p0 = p1;
        p1 = p2;
      }
      const double dp = k * (t * p1 - p0) / (t * t - 1);                 // P_k'
      const double d2p = (2 * t * dp - k * (k + 1) * p1) / (1 - t * t);  // P_k'' from the Legendre equation
      const double step = dp / d2p;
      t -= step;
      if (std::abs(step) < 1e-16) break;
    }
    out.push_back(t);
  }
  out.push_back(1.0);
  return out;
}

// k = 1, 2 and E, S at k = 3: the designs proven in proofs/thermal_product.md (Theorem 25's one-dimensional part).
std::optional<IntervalDesign> closed_form(CriterionKind c, int k) {
  IntervalDesign d;
  d.degree = k;
  d.closed_form = true;
  if (k == 1) {
    d.points = {-1, 1};
    d.weights = {0.5, 0.5};
  } else if (k == 2 && c == CriterionKind::E) {
    d.points = {-1, 0, 1};
    d.weights = {0.2, 0.6, 0.2};
  } else if (k == 2) {  // A and S
    d.points = {-1, 0, 1};
    d.weights = {0.25, 0.5, 0.25};
  } else if (k == 3 && (c == CriterionKind::E || c == CriterionKind::S)) {  // T_3's extrema
    d.points = {-1, -0.5, 0.5, 1};
    d.weights = c == CriterionKind::E ? std::vector<double>{19.0 / 150, 28.0 / 75, 28.0 / 75, 19.0 / 150}
                                      : std::vector<double>{1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6};
  } else {
    return std::nullopt;
  }
  return d;
}

// A symmetric design on -1, the interior points and 1 from free coordinates: the interior half-points
// as squashed values in (0, 1), the weights of the symmetric pairs (and the centre for even k) as a
// softmax. The centre is a support point whenever k is even (k - 1 interior points, odd count).
struct SymmetricDesigns {
  int k;
  int pairs() const { return (k - 1) / 2; }  // interior symmetric pairs
  bool centre() const { return k % 2 == 0; }
  int weight_count() const { return 1 + pairs() + (centre() ? 1 : 0); }
  int dimension() const { return pairs() + weight_count() - 1; }

  void decode(const Eigen::VectorXd& x, std::vector<double>& points, std::vector<double>& weights) const {
    std::vector<double> half{1.0};
    for (int i = 0; i < pairs(); ++i) half.push_back(1 / (1 + std::exp(-x(i))));
    std::vector<double> logit{0.0};
    for (int i = 0; i + 1 < weight_count(); ++i) logit.push_back(x(pairs() + i));
    double sum = 0;
    for (double& l : logit) sum += (l = std::exp(l));
    points.clear();
    weights.clear();
    for (int i = 0; i <= pairs(); ++i) {
      points.push_back(-half[static_cast<std::size_t>(i)]);
      points.push_back(half[static_cast<std::size_t>(i)]);
      weights.push_back(logit[static_cast<std::size_t>(i)] / sum / 2);
      weights.push_back(logit[static_cast<std::size_t>(i)] / sum / 2);
    }
    if (centre()) {
      points.push_back(0);
      weights.push_back(logit.back() / sum);
    }
  }
};

// Nelder and Mead's simplex on a small smooth-or-not function; restarted until it stops improving.
template <class F>
Eigen::VectorXd nelder_mead(const F& f, Eigen::VectorXd x0) {
  const int n = static_cast<int>(x0.size());
  for (int restart = 0; restart < 20; ++restart) {
    std::vector<Eigen::VectorXd> s{x0};
    for (int i = 0; i < n; ++i) {
      Eigen::VectorXd v = x0;
      v(i) += 0.5;
      s.push_back(v);
    }
    std::vector<double> fv;
    for (const auto& v : s) fv.push_back(f(v));
    for (int it = 0; it < 20000; ++it) {
      std::vector<int> order(s.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(),
                [&](int a, int b) { return fv[static_cast<std::size_t>(a)] < fv[static_cast<std::size_t>(b)]; });
      std::vector<Eigen::VectorXd> s2;
      std::vector<double> f2;
      for (int i : order) {
        s2.push_back(s[static_cast<std::size_t>(i)]);
        f2.push_back(fv[static_cast<std::size_t>(i)]);
      }
      s = s2;
      fv = f2;
      if (fv.back() - fv.front() <= 1e-15 * std::abs(fv.front())) break;
      Eigen::VectorXd c = Eigen::VectorXd::Zero(n);
      for (int i = 0; i < n; ++i) c += s[static_cast<std::size_t>(i)] / n;
      const Eigen::VectorXd r = c + (c - s.back());
      const double fr = f(r);
      if (fr < fv.front()) {
        const Eigen::VectorXd e = c + 2 * (c - s.back());
        const double fe = f(e);
        s.back() = fe < fr ? e : r;
        fv.back() = std::min(fe, fr);
      } else if (fr < fv[fv.size() - 2]) {
        s.back() = r;
        fv.back() = fr;
      } else {
        const Eigen::VectorXd k = c + 0.5 * (s.back() - c);
        const double fk = f(k);
        if (fk < fv.back()) {
          s.back() = k;
          fv.back() = fk;
        } else {
          for (std::size_t i = 1; i < s.size(); ++i) {
            s[i] = s[0] + 0.5 * (s[i] - s[0]);
            fv[i] = f(s[i]);
          }
        }
      }
    }
    const auto best = std::min_element(fv.begin(), fv.end()) - fv.begin();
    const double before = f(x0);
    x0 = s[static_cast<std::size_t>(best)];
    if (before - fv[static_cast<std::size_t>(best)] <= 1e-15 * std::abs(before)) break;
  }
  return x0;
}

// A lower bound on the criterion over every design, from convexity at the design found (a grid of
// 20001 temperatures stands for the interval; the bound is as good as that grid):
//   A:  tr M'^-1 >= 2 tr M^-1 - max f^T M^-2 f;
//   E:  lambda_min(M') <= f-average of v^T f f^T v <= max (v^T f)^2 for v M's smallest eigenvector;
//   S:  max_r (M'^-1)_rr >= sum_r w_r (M'^-1)_rr >= 2 sum_r w_r (M^-1)_rr - max f^T M^-1 W M^-1 f,
//       with w the best of a grid of weights on the parameters within 1e-6 of the largest variance.
double lower_bound(CriterionKind c, const Eigen::MatrixXd& m, int k) {
  const Eigen::MatrixXd inv = m.inverse();
  std::vector<Eigen::VectorXd> grid;
  for (int i = 0; i <= 20000; ++i) grid.push_back(powers(k, -1 + i / 10000.0));
  auto max_over = [&](const Eigen::MatrixXd& q) {
    double best = 0;
    for (const auto& f : grid) best = std::max(best, f.dot(q * f));
    return best;
  };
  if (c == CriterionKind::A) return 2 * inv.trace() - max_over(inv * inv);
  if (c == CriterionKind::E) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(m);
    const Eigen::VectorXd v = eig.eigenvectors().col(0);
    return 1 / max_over(v * v.transpose());
  }
  std::vector<int> active;
  const double top = inv.diagonal().maxCoeff();
  for (int r = 0; r <= k; ++r)
    if (inv(r, r) >= top * (1 - 1e-6)) active.push_back(r);
  double best = 0;
  const int steps = active.size() == 1 ? 1 : 200;
  for (int s = 0; s <= steps; ++s) {  // weight s/steps on the first active parameter, the rest evenly
    Eigen::VectorXd w = Eigen::VectorXd::Zero(k + 1);
    if (active.size() == 1) {
      w(active[0]) = 1;
    } else {
      w(active[0]) = double(s) / steps;
      for (std::size_t i = 1; i < active.size(); ++i)
        w(active[i]) = (1 - double(s) / steps) / double(active.size() - 1);
    }
    const Eigen::MatrixXd W = w.asDiagonal();
    best = std::max(best, 2 * (W * inv).trace() - max_over(inv * W * inv));
    if (active.size() == 1) break;
  }
  return best;
}

}  // namespace

Eigen::MatrixXd interval_information(int degree, const std::vector<double>& points,
                                     const std::vector<double>& weights) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(degree + 1, degree + 1);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::VectorXd f = powers(degree, points[i]);
    m += weights[i] * f * f.transpose();
  }
  return m;
}

std::optional<IntervalDesign> optimal_interval_design(CriterionKind c, int k) {
  if (!information_criterion(c, Eigen::MatrixXd::Identity(1, 1))) return std::nullopt;
  std::optional<IntervalDesign> d;
  if (c == CriterionKind::D) {
    d = IntervalDesign{
        k, lobatto_points(k), std::vector<double>(static_cast<std::size_t>(k + 1), 1.0 / (k + 1)), 0, 0, true};
  } else {
    d = closed_form(c, k);
  }
  if (!d) {  // A from k = 3, E and S from k = 4: the best symmetric de la Garza design from the Lobatto design
    const SymmetricDesigns family{k};
    auto objective = [&](const Eigen::VectorXd& x) {
      std::vector<double> p, w;
      family.decode(x, p, w);
      return *information_criterion(c, interval_information(k, p, w));
    };
    Eigen::VectorXd x0 = Eigen::VectorXd::Zero(family.dimension());
    const std::vector<double> lobatto = lobatto_points(k);
    for (int i = 0; i < family.pairs(); ++i) {
      const double t = lobatto[static_cast<std::size_t>(k - 1 - i)];
      x0(i) = std::log(t / (1 - t));
    }
    const Eigen::VectorXd x = nelder_mead(objective, x0);
    d = IntervalDesign{};
    d->degree = k;
    family.decode(x, d->points, d->weights);
  }
  // Increasing points, their weights alongside.
  std::vector<std::size_t> order(d->points.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return d->points[a] < d->points[b]; });
  IntervalDesign sorted = *d;
  for (std::size_t i = 0; i < order.size(); ++i) {
    sorted.points[i] = d->points[order[i]];
    sorted.weights[i] = d->weights[order[i]];
  }
  const Eigen::MatrixXd m = interval_information(k, sorted.points, sorted.weights);
  sorted.value = *information_criterion(c, m);
  sorted.lower_bound = sorted.closed_form      ? sorted.value
                       : c == CriterionKind::D ? sorted.value
                                               : std::min(sorted.value, lower_bound(c, m, k));
  return sorted;
}

}  // namespace scalcal
