// Smooth criteria as small value types of the information matrix M alone: each gives phi(M) and
// the pieces of its first two derivatives, d phi = tr(G dM) and dG = c (A dM B + B dM A), which
// is all a solver over the positions needs (it never learns which criterion it serves).
#pragma once
#include <cmath>

#include <Eigen/Cholesky>

#include "numeric/criteria/derivatives.hpp"

namespace scalcal {

template <class Scalar>
struct MatrixDerivatives {
  Scalar value{};
  Mat9T<Scalar> G, A, B;
  Scalar c{};
  bool same_sides = false;  // A == B: the Hessian needs half the products
};

// log D = -log det(M / N): smooth, scale-free, and invariant under rotations of the program.
struct LogDetCriterion {
  // False when M is not numerically positive definite (the value is then meaningless).
  template <class Scalar>
  static bool value(const Mat9T<Scalar>& M, int n, Scalar& out) {
    Eigen::LLT<Mat9T<Scalar>> llt(M);
    if (llt.info() != Eigen::Success) return false;
    out = log_d(llt, n);
    return true;
  }

  // G = -K, dG = K dM K.
  template <class Scalar>
  static bool derivatives(const Mat9T<Scalar>& M, int n, MatrixDerivatives<Scalar>& d) {
    Eigen::LLT<Mat9T<Scalar>> llt(M);
    if (llt.info() != Eigen::Success) return false;
    d.value = log_d(llt, n);
    d.A = llt.solve(Mat9T<Scalar>::Identity());
    d.A = (d.A + d.A.transpose()).eval() / Scalar(2);
    d.B = d.A;
    d.G = -d.A;
    d.c = Scalar(1) / Scalar(2);
    d.same_sides = true;
    return true;
  }

 private:
  // 9 log N - log det M from the Cholesky factor of M.
  template <class Scalar>
  static Scalar log_d(const Eigen::LLT<Mat9T<Scalar>>& llt, int n) {
    using std::log;
    Scalar logdet(0);
    for (int i = 0; i < 9; ++i) logdet += log(llt.matrixLLT()(i, i));
    return Scalar(9) * log(Scalar(n)) - Scalar(2) * logdet;
  }
};

// A = N trace K: G = -N K^2, dG = N (K dM K^2 + K^2 dM K).
struct TraceCriterion {
  template <class Scalar>
  static bool value(const Mat9T<Scalar>& M, int n, Scalar& out) {
    bool ok = false;
    out = Scalar(n) * inverse_information(M, ok).trace();
    return ok;
  }

  template <class Scalar>
  static bool derivatives(const Mat9T<Scalar>& M, int n, MatrixDerivatives<Scalar>& d) {
    bool ok = false;
    d.A = inverse_information(M, ok);
    if (!ok) return false;
    d.A = (d.A + d.A.transpose()).eval() / Scalar(2);
    d.B = d.A * d.A;
    d.value = Scalar(n) * d.A.trace();
    d.G = Scalar(-n) * d.B;
    d.c = Scalar(n);
    d.same_sides = false;
    return true;
  }
};

}  // namespace scalcal
