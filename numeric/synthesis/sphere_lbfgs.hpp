// Riemannian L-BFGS over N unit vectors for a smooth criterion of M: the local solver of the D and A
// multistarts at large N, where a Newton step (a dense 2N x 2N factorisation and 3N x 3N Gram
// matrices) costs O(N^3) while an L-BFGS step costs O(N P^2). Curvature pairs live in R^3N and are
// projected onto the current tangent spaces (transport by projection), the retraction normalises.
// SphereLbfgsSolver is compiled once per model (the criterion is a SmoothOps); SphereLbfgs<C> is its
// name for one criterion type.
#pragma once
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

#include "numeric/criteria/derivatives.hpp"
#include "numeric/model/design.hpp"
#include "numeric/program/summary.hpp"
#include "numeric/synthesis/criterion_ops.hpp"
#include "numeric/synthesis/synthesis_models.hpp"

namespace scalcal {

struct SphereLbfgsOptions {
  // As SphereNewtonOptions: 2-norm of the Riemannian gradient relative to max(1, |value|).
  double gradient_tolerance = 1e-9;
  int max_iterations = 2000;
  int memory = 12;        // curvature pairs kept
  double max_turn = 0.5;  // radians, per position, of the first trial step of a line search
};

struct SphereLbfgsResult {
  Summary summary;  // converged: the Riemannian gradient fell below its tolerance; failed: rank < P at the start
  bool converged() const { return summary.converged(); }
  int iterations = 0;
  int evaluations = 0;
  double value = 0;  // the criterion's own objective (log D for D), not normalised
  double gradient_norm = 0;
};

template <class Model = Paper9Model>
class SphereLbfgsSolver {
 public:
  static constexpr int P = Model::kParameters;
  using VecX = Eigen::VectorXd;

  explicit SphereLbfgsSolver(SmoothOps<double, P> criterion, SphereLbfgsOptions options = {})
      : criterion_(criterion), options_(options) {}

  // Improves `eta` in place (each position stays a unit vector).
  SphereLbfgsResult run(std::vector<Vec3>& eta);

 private:
  struct Pair {
    VecX s, y;
    double rho;
  };

  // The criterion's objective and its Riemannian gradient (Euclidean gradient projected onto each
  // tangent plane), in R^3N. False when M is not positive definite.
  bool evaluate(const std::vector<Vec3>& eta, double& f, VecX& g) const;

  static void project(const std::vector<Vec3>& eta, VecX& v) {
    for (std::size_t i = 0; i < eta.size(); ++i) {
      auto vi = v.segment<3>(3 * static_cast<int>(i));
      vi -= eta[i].dot(vi) * eta[i];
    }
  }

  // direction = -H g by the two-loop recursion over the (transported) pairs, then projected onto
  // the tangent spaces at eta.
  static void two_loop(std::deque<Pair>& pairs, const VecX& g, const std::vector<Vec3>& eta, VecX& direction);

  SmoothOps<double, P> criterion_;
  SphereLbfgsOptions options_;
};

// The solver for one criterion type.
template <SmoothCriterion Criterion, class Model = Paper9Model>
class SphereLbfgs : public SphereLbfgsSolver<Model> {
 public:
  explicit SphereLbfgs(SphereLbfgsOptions options = {})
      : SphereLbfgsSolver<Model>(smooth_ops<Criterion, double, Model::kParameters>(), options) {}
};

template <class Model>
SphereLbfgsResult SphereLbfgsSolver<Model>::run(std::vector<Vec3>& eta) {
  SphereLbfgsResult out;
  const int n = static_cast<int>(eta.size());
  for (auto& e : eta) e.normalize();
  double f = 0;
  VecX g(3 * n);
  if (!evaluate(eta, f, g)) return out;
  out.summary.termination = Termination::not_converged;
  out.summary.message = "stopped before its gradient tolerance";
  ++out.evaluations;
  std::deque<Pair> pairs;
  std::vector<Vec3> trial(eta.size());
  VecX g_trial(3 * n), direction(3 * n);
  int stalled = 0;
  while (true) {
    const double gnorm = g.norm();
    out.value = f;
    out.gradient_norm = gnorm;
    const double tolerance = options_.gradient_tolerance * std::max(1.0, std::abs(f));
    if (gnorm <= tolerance || (stalled >= 3 && gnorm <= 100 * tolerance)) {
      out.summary.termination = Termination::converged;
      out.summary.message = "Riemannian gradient below tolerance (L-BFGS)";
      return out;
    }
    if (out.iterations >= options_.max_iterations || stalled >= 3) return out;
    two_loop(pairs, g, eta, direction);
    double slope = g.dot(direction);
    if (!(slope < 0)) {  // not a descent direction after transport: restart from the gradient
      pairs.clear();
      direction = -g;
      slope = -gnorm * gnorm;
    }
    // The first step of an iteration is the quasi-Newton one (1), shortened so no position turns
    // by more than max_turn: beyond that the retraction bends the step away from its model.
    double turn = 0;
    for (int i = 0; i < n; ++i) turn = std::max(turn, direction.segment<3>(3 * i).norm());
    double t = std::min(1.0, options_.max_turn / std::max(turn, std::numeric_limits<double>::min()));
    const double rounding = 8 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(f));
    bool accepted = false;
    double f_trial = 0;
    for (int attempt = 0; attempt < 40; ++attempt, t *= 0.25) {
      for (int i = 0; i < n; ++i)
        trial[static_cast<std::size_t>(i)] =
            (eta[static_cast<std::size_t>(i)] + t * direction.segment<3>(3 * i)).normalized();
      ++out.evaluations;
      if (!evaluate(trial, f_trial, g_trial)) continue;
      // Armijo, or (below rounding, where the decrease is noise) no increase beyond rounding.
      if (f_trial <= f + 1e-4 * t * slope || (std::abs(t * slope) <= rounding && f_trial <= f + rounding)) {
        accepted = true;
        break;
      }
    }
    if (!accepted) return out;
    stalled = std::abs(f - f_trial) <= rounding ? stalled + 1 : 0;
    Pair p{VecX(3 * n), VecX(3 * n), 0};
    for (int i = 0; i < n; ++i)
      p.s.template segment<3>(3 * i) = trial[static_cast<std::size_t>(i)] - eta[static_cast<std::size_t>(i)];
    project(trial, p.s);
    VecX g_old = g;
    project(trial, g_old);
    p.y = g_trial - g_old;
    const double sy = p.s.dot(p.y);
    // Only pairs of positive curvature keep the inverse-Hessian model positive definite.
    if (sy > 1e-12 * p.s.norm() * p.y.norm()) {
      p.rho = 1 / sy;
      pairs.push_back(std::move(p));
      if (static_cast<int>(pairs.size()) > options_.memory) pairs.pop_front();
    }
    eta.swap(trial);
    f = f_trial;
    g.swap(g_trial);
    ++out.iterations;
  }
}

template <class Model>
bool SphereLbfgsSolver<Model>::evaluate(const std::vector<Vec3>& eta, double& f, VecX& g) const {
  MatrixDerivatives<double, P> d;
  if (!criterion_.derivatives(information_matrix<Model>(eta), static_cast<int>(eta.size()), d)) return false;
  f = d.value;
  for (std::size_t i = 0; i < eta.size(); ++i) {
    const RowT<Model, double> w = d.G * Model::row(eta[i]);
    const Vec3 egrad = 2.0 * (Model::jacobian(eta[i]).transpose() * w);
    g.segment<3>(3 * static_cast<int>(i)) = egrad - eta[i].dot(egrad) * eta[i];
  }
  return true;
}

template <class Model>
void SphereLbfgsSolver<Model>::two_loop(std::deque<Pair>& pairs, const VecX& g, const std::vector<Vec3>& eta,
                                        VecX& direction) {
  for (auto& p : pairs) {
    project(eta, p.s);
    project(eta, p.y);
  }
  VecX q = g;
  std::vector<double> alpha(pairs.size());
  for (std::size_t k = pairs.size(); k-- > 0;) {
    alpha[k] = pairs[k].rho * pairs[k].s.dot(q);
    q -= alpha[k] * pairs[k].y;
  }
  if (!pairs.empty()) {
    const Pair& last = pairs.back();
    q *= last.s.dot(last.y) / last.y.squaredNorm();
  }
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const double beta = pairs[k].rho * pairs[k].y.dot(q);
    q += (alpha[k] - beta) * pairs[k].s;
  }
  direction = -q;
  project(eta, direction);
}

// Compiled once per model of this build, in its synthesis unit (numeric/synthesis/model_unit.cpp.in).
#define SCALCAL_SPHERE_LBFGS_INSTANCES(prefix, M) prefix template class SphereLbfgsSolver<M>;
#define SCALCAL_EXTERN_SPHERE_LBFGS(M) SCALCAL_SPHERE_LBFGS_INSTANCES(extern, M)
SCALCAL_FOR_EACH_SYNTHESIS_MODEL(SCALCAL_EXTERN_SPHERE_LBFGS)
#undef SCALCAL_EXTERN_SPHERE_LBFGS

}  // namespace scalcal
