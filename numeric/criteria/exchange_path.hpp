// The information matrix along a vertex exchange, M(a) = M + a (u u^T - v v^T) (mass a moves from the
// candidate with row v to the one with row u: region/optimal_measure.hpp), reduced to the six numbers a
// criterion of K = M^-1 needs to take its value at any a in O(1). By Woodbury's identity, with
// W = (u, v) and C = diag(1, -1),
//   K(a) = K - a K W T(a)^-1 C W^T K,   T(a) = I + a C W^T K W,   det M(a) = det M det T(a).
// The line search of an exchange takes 42 values: an O(P^3) factorisation each without this.
#pragma once
#include <Eigen/Cholesky>

namespace scalcal {

struct ExchangePath {
  double uKu = 0, uKv = 0, vKv = 0;     // W^T K W
  double uKKu = 0, uKKv = 0, vKKv = 0;  // W^T K^2 W

  // det M(a) / det M = det T(a). It is 1 at a = 0 and concave in a (its a^2 coefficient is
  // uKv^2 - uKu vKv <= 0 by Cauchy-Schwarz), so M(a') stays positive definite for every a' in
  // [0, a] exactly when it is positive at a.
  double determinant_ratio(double a) const { return (1 + a * uKu) * (1 - a * vKv) + a * a * uKv * uKv; }

  // tr K(a) - tr K = -a tr(T^-1 C W^T K^2 W), written out for the 2 x 2 T.
  double trace_change(double a) const {
    return -a * (uKKu - vKKv + a * (2 * uKv * uKKv - vKv * uKKu - uKu * vKKv)) / determinant_ratio(a);
  }
};

// The path from M's factorisation and the two rows.
template <int P>
ExchangePath exchange_path(const Eigen::LLT<Eigen::Matrix<double, P, P>>& llt, const Eigen::Matrix<double, P, 1>& u,
                           const Eigen::Matrix<double, P, 1>& v) {
  const Eigen::Matrix<double, P, 1> Ku = llt.solve(u), Kv = llt.solve(v);
  ExchangePath p;
  p.uKu = u.dot(Ku);
  p.uKv = u.dot(Kv);
  p.vKv = v.dot(Kv);
  p.uKKu = Ku.dot(Ku);
  p.uKKv = Ku.dot(Kv);
  p.vKKv = Kv.dot(Kv);
  return p;
}

}  // namespace scalcal
