// Riemannian Newton over N unit vectors for a smooth criterion of M (criteria/criterion.hpp): the
// exact Hessian in 2N tangent coordinates, a Levenberg-Marquardt shift mu = theta |grad| (so the
// rank-deficient Hessian at a D optimum, singular along rotations, still gives quadratic
// convergence), and normalisation as the retraction. The fast local solver of the D and A
// multistarts: no allocation inside a step beyond a few 2N-sized matrices, one Cholesky per try.
// SphereNewtonSolver is compiled once per model (the criterion is a SmoothOps); SphereNewton<C> is
// its name for one criterion type.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "numeric/criteria/derivatives.hpp"
#include "numeric/model/design.hpp"
#include "numeric/program/summary.hpp"
#include "numeric/synthesis/criterion_ops.hpp"
#include "numeric/synthesis/synthesis_models.hpp"

namespace scalcal {

struct SphereNewtonOptions {
  // 2-norm of the Riemannian gradient of the criterion, relative to max(1, |value|). Rounding
  // leaves 1e-9..1e-8 at some optima (D at N = 9, A at N = 12), where the value has long been
  // exact to double precision.
  double gradient_tolerance = 1e-9;
  int max_iterations = 200;
  double initial_shift = 1;  // theta at the start
  double max_turn = 1;       // radians, per position and step
};

struct SphereNewtonResult {
  Summary summary;  // converged: the Riemannian gradient fell below its tolerance; failed: rank < P at the start
  bool converged() const { return summary.converged(); }
  int iterations = 0;   // accepted Newton steps
  int evaluations = 0;  // criterion values at trial programs (rejected steps included)
  double value = 0;     // the criterion's own objective (log D for D), not normalised
  double gradient_norm = 0;
};

// An orthonormal basis of the tangent plane at e, built from the axis least aligned with e so
// it stays well conditioned at the poles.
template <class Scalar>
Eigen::Matrix<Scalar, 3, 2> tangent_basis(const Vec3T<Scalar>& e) {
  using std::abs;
  int k = 0;
  for (int a = 1; a < 3; ++a)
    if (abs(e(a)) < abs(e(k))) k = a;
  Vec3T<Scalar> axis = Vec3T<Scalar>::Zero();
  axis(k) = Scalar(1);
  Eigen::Matrix<Scalar, 3, 2> basis;
  basis.col(0) = (axis - e(k) * e).normalized();
  basis.col(1) = e.cross(Vec3T<Scalar>(basis.col(0)));
  return basis;
}

template <class Model = Paper9Model, class Scalar = double>
class SphereNewtonSolver {
 public:
  using MatX = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  using VecX = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  static constexpr int P = Model::kParameters;
  using MatPX = Eigen::Matrix<Scalar, P, Eigen::Dynamic>;
  using MatP = InformationT<Model, Scalar>;
  using Basis = Eigen::Matrix<Scalar, 3, 2>;

  explicit SphereNewtonSolver(SmoothOps<Scalar, P> criterion, SphereNewtonOptions options = {})
      : criterion_(criterion), options_(options) {}

  // The Newton model at eta: criterion value, Riemannian gradient and (full, symmetric) Hessian
  // in the coordinates t of eta_i(t) = normalise(eta_i + tangent_basis(eta_i) t_i). False when
  // M is not positive definite.
  bool local_model(const std::vector<Vec3T<Scalar>>& eta, Scalar& value, VecX& gradient, MatX& hessian);

  // Improves `eta` in place (each position stays a unit vector).
  SphereNewtonResult run(std::vector<Vec3T<Scalar>>& eta);

 private:
  // out = X^T W X for X = [T U] (P x 3N) as a lower triangle: through the Cholesky factor of W
  // when it has one (a symmetric rank-P update, half the products), else a plain product.
  void gram(const MatP& W, MatX& out);

  // The Riemannian gradient g_ and Hessian H_ (lower triangle) in the tangent bases of every
  // position. With U = [h_i], T = [J_i B_i], block (i, j) of the Euclidean Hessian is (derivatives.hpp)
  //   2c [ (h_j^T B h_i) T_i^T A T_j + (h_j^T A h_i) T_i^T B T_j + (T_i^T A h_j)(T_j^T B h_i)^T + (A <-> B) ],
  // so the Gram matrices X^T A X and X^T B X of X = [T U] give all of it.
  void assemble(const std::vector<Vec3T<Scalar>>& eta, const MatrixDerivatives<Scalar, P>& d);

  SmoothOps<Scalar, P> criterion_;
  SphereNewtonOptions options_;
  MatPX X_, V_;
  std::vector<Basis> bases_;
  std::vector<JacobianT<Model, Scalar>> J_;
  MatX PA_, PB_, H_, shifted_;
  VecX g_, step_;
  Eigen::LLT<MatX> llt_;
};

// The solver for one criterion type.
template <SmoothCriterion Criterion, class Model = Paper9Model, class Scalar = double>
class SphereNewton : public SphereNewtonSolver<Model, Scalar> {
 public:
  explicit SphereNewton(SphereNewtonOptions options = {})
      : SphereNewtonSolver<Model, Scalar>(smooth_ops<Criterion, Scalar, Model::kParameters>(), options) {}
};

template <class Model, class Scalar>
bool SphereNewtonSolver<Model, Scalar>::local_model(const std::vector<Vec3T<Scalar>>& eta, Scalar& value,
                                                    VecX& gradient, MatX& hessian) {
  MatrixDerivatives<Scalar, P> d;
  if (!criterion_.derivatives(information_matrix<Model>(eta), static_cast<int>(eta.size()), d)) return false;
  assemble(eta, d);
  value = d.value;
  gradient = g_;
  hessian = H_.template selfadjointView<Eigen::Lower>();
  return true;
}

template <class Model, class Scalar>
SphereNewtonResult SphereNewtonSolver<Model, Scalar>::run(std::vector<Vec3T<Scalar>>& eta) {
  SphereNewtonResult out;
  const int n = static_cast<int>(eta.size());
  for (auto& e : eta) e.normalize();
  Scalar theta(options_.initial_shift);
  std::vector<Vec3T<Scalar>> trial(eta.size());
  int stalled = 0;  // consecutive accepted steps that changed the value by rounding only
  MatP M = information_matrix<Model>(eta), M_trial;  // M of an accepted trial is kept, not rebuilt
  while (true) {
    MatrixDerivatives<Scalar, P> d;
    if (!criterion_.derivatives(M, n, d)) {  // rank < P: no Newton model
      out.summary.termination = Termination::failed;
      out.summary.message = "rank-deficient program: no Newton model";
      return out;
    }
    out.summary.termination = Termination::not_converged;
    out.summary.message = "stopped before its gradient tolerance";
    assemble(eta, d);
    const Scalar gnorm = g_.norm();
    out.value = static_cast<double>(d.value);
    out.gradient_norm = static_cast<double>(gnorm);
    using std::abs;
    const Scalar tolerance = Scalar(options_.gradient_tolerance) * std::max(Scalar(1), abs(d.value));
    // A stall (the value no longer moves at double precision) counts as converged when the
    // gradient is within rounding of the tolerance.
    if (gnorm <= tolerance || (stalled >= 3 && gnorm <= Scalar(100) * tolerance)) {
      out.summary.termination = Termination::converged;
      out.summary.message = "Riemannian gradient below tolerance (Newton)";
      return out;
    }
    if (out.iterations >= options_.max_iterations || stalled >= 3) return out;
    // The shift never falls below sqrt(eps) |H|: along the null directions (rotations) the
    // gradient is pure rounding, and dividing rounding by a vanishing shift would turn the
    // program by an angle whose second-order effect undoes Newton's accuracy.
    using std::sqrt;
    const Scalar floor = sqrt(std::numeric_limits<Scalar>::epsilon()) * H_.diagonal().cwiseAbs().maxCoeff();
    bool accepted = false;
    for (int attempt = 0; attempt < 60 && !accepted; ++attempt) {
      shifted_ = H_;
      shifted_.diagonal().array() += theta * gnorm + floor;
      llt_.compute(shifted_);
      if (llt_.info() != Eigen::Success) {  // negative curvature beyond the shift
        theta *= Scalar(8);
        continue;
      }
      step_ = -llt_.solve(g_);
      // A position turned by more than max_turn is outside any use of the quadratic model:
      // shrink the whole step, keeping its direction.
      Scalar turn(0);
      for (int i = 0; i < n; ++i) turn = std::max(turn, Scalar(step_.template segment<2>(2 * i).norm()));
      if (turn > Scalar(options_.max_turn)) step_ *= Scalar(options_.max_turn) / turn;
      for (int i = 0; i < n; ++i)
        trial[static_cast<std::size_t>(i)] =
            (eta[static_cast<std::size_t>(i)] + bases_[static_cast<std::size_t>(i)] * step_.template segment<2>(2 * i))
                .normalized();
      Scalar f_trial;
      ++out.evaluations;
      const Scalar predicted =
          -(g_.dot(step_) + Scalar(0.5) * step_.dot(H_.template selfadjointView<Eigen::Lower>() * step_));
      M_trial = information_matrix<Model>(trial);
      if (criterion_.objective(M_trial, n, f_trial) && predicted > Scalar(0)) {
        // Below rounding the ratio test is noise: a step that leaves the value unchanged to
        // rounding is taken, and the gradient decides convergence.
        const Scalar rounding = Scalar(8) * std::numeric_limits<Scalar>::epsilon() * std::max(Scalar(1), abs(d.value));
        const Scalar rho = (d.value - f_trial) / predicted;
        const bool in_rounding = predicted <= rounding && abs(d.value - f_trial) <= Scalar(2) * rounding;
        if (rho > Scalar(1e-4) || in_rounding) {
          accepted = true;
          stalled = abs(d.value - f_trial) <= rounding ? stalled + 1 : 0;
          eta.swap(trial);
          M = M_trial;
          if (rho > Scalar(0.75) || in_rounding)
            theta = std::max(theta / Scalar(4), Scalar(1e-4));
          else if (rho < Scalar(0.25))
            theta *= Scalar(2);
          break;
        }
      }
      theta *= Scalar(4);
    }
    if (!accepted) return out;  // no descent from here at this precision
    ++out.iterations;
  }
}

template <class Model, class Scalar>
void SphereNewtonSolver<Model, Scalar>::gram(const MatP& W, MatX& out) {
  const int cols = static_cast<int>(X_.cols());
  out.setZero(cols, cols);
  Eigen::LLT<MatP> factor(W);
  if (factor.info() == Eigen::Success) {
    V_.noalias() = factor.matrixU() * X_;
    out.template selfadjointView<Eigen::Lower>().rankUpdate(V_.transpose());
  } else {
    V_.noalias() = W * X_;
    out.noalias() = X_.transpose() * V_;
  }
}

template <class Model, class Scalar>
void SphereNewtonSolver<Model, Scalar>::assemble(const std::vector<Vec3T<Scalar>>& eta,
                                                 const MatrixDerivatives<Scalar, P>& d) {
  const int n = static_cast<int>(eta.size()), m = 2 * n;
  X_.resize(P, 3 * n);
  bases_.resize(eta.size());
  J_.resize(eta.size());
  for (int i = 0; i < n; ++i) {
    const auto& e = eta[static_cast<std::size_t>(i)];
    X_.col(m + i) = Model::row(e);
    J_[static_cast<std::size_t>(i)] = Model::jacobian(e);
    bases_[static_cast<std::size_t>(i)] = tangent_basis(e);
    X_.template middleCols<2>(2 * i) = J_[static_cast<std::size_t>(i)] * bases_[static_cast<std::size_t>(i)];
  }
  gram(d.A, PA_);
  if (!d.same_sides) gram(d.B, PB_);
  const MatX& PB = d.same_sides ? PA_ : PB_;
  // Entries of the lower triangles: Q(2i+a, 2j+b) = P(2i+a, 2j+b) (a, b in the lower part),
  // R(2i+a, j) = T_i,a^T W h_j = P(m + j, 2i + a), S(i, j) = P(m + i, m + j), i >= j.
  const auto Q = [](const MatX& P, int r, int c) { return r >= c ? P(r, c) : P(c, r); };
  const auto R = [m](const MatX& P, int r, int j) { return P(m + j, r); };
  const auto S = [m](const MatX& P, int i, int j) { return i >= j ? P(m + i, m + j) : P(m + j, m + i); };
  H_.resize(m, m);
  const Scalar two_c = Scalar(2) * d.c;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j)
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) {
          const int r = 2 * i + a, c = 2 * j + b;
          if (c > r) continue;
          H_(r, c) = two_c * (S(PB, i, j) * Q(PA_, r, c) + S(PA_, i, j) * Q(PB, r, c) + R(PA_, r, j) * R(PB, c, i) +
                              R(PB, r, j) * R(PA_, c, i));
        }
  // Diagonal terms: the curvature of h (T(G h_i)), J^T G J, and the sphere's own curvature
  // -(eta . grad) that turns the Euclidean Hessian into the Riemannian one.
  g_.resize(m);
  const Scalar two(2);
  for (int i = 0; i < n; ++i) {
    const auto& Ji = J_[static_cast<std::size_t>(i)];
    const auto& Bi = bases_[static_cast<std::size_t>(i)];
    const RowT<Model, Scalar> w = d.G * X_.col(m + i);
    const Vec3T<Scalar> egrad = two * (Ji.transpose() * w);
    g_.template segment<2>(2 * i) = Bi.transpose() * egrad;
    const Mat3T<Scalar> curvature = Model::curvature(w, eta[static_cast<std::size_t>(i)]);
    const Eigen::Matrix<Scalar, P, 2> Ti = X_.template middleCols<2>(2 * i);
    const Eigen::Matrix<Scalar, 2, 2> extra =
        two * (Bi.transpose() * curvature * Bi) + two * (Ti.transpose() * d.G * Ti) -
        eta[static_cast<std::size_t>(i)].dot(egrad) * Eigen::Matrix<Scalar, 2, 2>::Identity();
    H_(2 * i, 2 * i) += extra(0, 0);
    H_(2 * i + 1, 2 * i) += extra(1, 0);
    H_(2 * i + 1, 2 * i + 1) += extra(1, 1);
  }
}

// Compiled once per model of this build, in its synthesis unit (numeric/synthesis/model_unit.cpp.in).
#define SCALCAL_SPHERE_NEWTON_INSTANCES(prefix, M) prefix template class SphereNewtonSolver<M, double>;
#define SCALCAL_EXTERN_SPHERE_NEWTON(M) SCALCAL_SPHERE_NEWTON_INSTANCES(extern, M)
SCALCAL_FOR_EACH_SYNTHESIS_MODEL(SCALCAL_EXTERN_SPHERE_NEWTON)
#undef SCALCAL_EXTERN_SPHERE_NEWTON

}  // namespace scalcal
