// Existence and uniqueness of a zero of a square system in a box, by the Krawczyk test in MPFI:
// K(X) = x - Y F(x) + (I - Y F'(X)) (X - x) inside the interior of X proves that X holds exactly
// one zero (Krawczyk 1969; Rump's form). Newton in MPFR brings x close first.
//
// A System provides size() and, for T in {Real, Interval},
//   void eval(const Eigen::Matrix<T, -1, 1>& x, Eigen::Matrix<T, -1, 1>& F, Eigen::Matrix<T, -1, -1>* J) const.
#pragma once
#include <optional>

#include <Eigen/LU>

#include "numeric/certify/interval.hpp"
#include "numeric/certify/loops.hpp"

namespace scalcal::certify_detail {

struct NewtonOutcome {
  VecX x;
  Real residual;      // inf-norm of F at x
  Real displacement;  // inf-norm of x - start
  int iterations = 0;
};

// Newton's method in MPFR until |F| stops shrinking or falls under `tolerance`.
template <class System>
NewtonOutcome newton(const System& s, const VecX& start, const Real& tolerance, int max_iterations = 40) {
  NewtonOutcome out{start, Real(0), Real(0), 0};
  VecX F;
  MatX J;
  s.eval(out.x, F, &J);
  out.residual = F.cwiseAbs().maxCoeff();
  for (; out.iterations < max_iterations && out.residual > tolerance; ++out.iterations) {
    const VecX step = J.partialPivLu().solve(F);
    const VecX next = out.x - step;
    VecX Fn;
    MatX Jn;
    s.eval(next, Fn, &Jn);
    const Real rn = Fn.cwiseAbs().maxCoeff();
    if (!(rn < out.residual)) break;  // no progress: x is as good as this precision allows
    out.x = next;
    F = Fn;
    J = Jn;
    out.residual = rn;
  }
  out.displacement = (out.x - start).cwiseAbs().maxCoeff();
  return out;
}

struct KrawczykBox {
  IVecX box;    // contains exactly one zero
  Real radius;  // half-width of the box in the inf-norm, about x
};

// Tries boxes of growing radius about x (an approximate zero); nullopt when none passes.
template <class System>
std::optional<KrawczykBox> krawczyk(const System& s, const VecX& x) {
  const Eigen::Index n = x.size();
  IVecX Fx;
  IMatX Jx;
  s.eval(points(x), Fx, &Jx);
  const MatX Y = midpoints(Jx).partialPivLu().inverse();
  IMatX Yi(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) Yi(i, j) = point(Y(i, j));
  const IVecX YF = times(Yi, Fx);
  Real step(0);
  for (Eigen::Index i = 0; i < n; ++i) step = std::max(step, mag(YF(i)));
  // The box must hold the Newton step; the floor keeps it above the rounding level.
  const Real floor = pow(Real(10), -Real(int(Real::default_precision()) - 10));
  Real r = std::max(step * 16, floor);
  const IVecX xi = points(x);
  for (int attempt = 0; attempt < 12; ++attempt, r *= 100) {
    IVecX X(n);
    for (Eigen::Index i = 0; i < n; ++i) X(i) = around(x(i), r);
    IVecX FX;
    IMatX JX;
    s.eval(X, FX, &JX);
    IMatX R = -times(Yi, JX);
    for (Eigen::Index i = 0; i < n; ++i) R(i, i) += Interval(1);
    const IVecX K = xi - YF + times(R, IVecX(X - xi));
    bool inside = true;
    for (Eigen::Index i = 0; i < n && inside; ++i) inside = interior(K(i), X(i));
    if (inside) return KrawczykBox{X, r};
  }
  return std::nullopt;
}

}  // namespace scalcal::certify_detail
