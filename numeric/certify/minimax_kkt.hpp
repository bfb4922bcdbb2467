// A local optimum of S = N max_r K_rr as a square system in (x, s, mu_R): the active diagonal
// entries R equal s, their weights mu (mu >= 0, sum 1) balance their gradients, and
//   F = (sum_r mu_r grad K_rr, K_rr - s for r in R, sum mu - 1).
// Its Jacobian holds the Hessian of tr(W K), W = diag(mu): 2 tr(K W K X_a K X_b) - tr(K W K X_ab).
#pragma once
#include <vector>

#include "numeric/certify/critical_point.hpp"

namespace scalcal::certify_detail {

struct MinimaxKktSystem {
  const SphereChart* chart;
  FreeCoordinates coordinates;  // the chart coordinates; s and mu follow them in the unknowns
  std::vector<int> active;      // R: indices of the active diagonal entries of K

  int size() const { return coordinates.size() + 1 + static_cast<int>(active.size()); }

  // K of the program at chart coordinates x (the first coordinates.size() unknowns).
  template <class T>
  Square9<T> inverse_information(const Eigen::Matrix<T, -1, 1>& unknowns) const {
    T log_det;
    return spd_inverse(
        assemble_information(*chart, coordinates.full(Eigen::Matrix<T, -1, 1>(unknowns.head(coordinates.size())))),
        log_det);
  }

  template <class T>
  void eval(const Eigen::Matrix<T, -1, 1>& unknowns, Eigen::Matrix<T, -1, 1>& F, Eigen::Matrix<T, -1, -1>* J) const {
    const int m = coordinates.size(), na = static_cast<int>(active.size());
    const T s = unknowns(m);
    std::vector<std::array<Jet2<T>, 9>> rows;
    T log_det;
    const Square9<T> K = spd_inverse(
        assemble_information(*chart, coordinates.full(Eigen::Matrix<T, -1, 1>(unknowns.head(m))), &rows), log_det);
    Square9<T> W = Square9<T>::Zero();
    for (int q = 0; q < na; ++q) W(active[q], active[q]) = unknowns(m + 1 + q);
    const Square9<T> KWK = times(K, times(W, K));
    const Square9<T> G = -KWK;
    F.resize(size());
    std::vector<Column9<T>> g, h;
    row_derivatives(rows, coordinates, g, h);
    std::vector<Square9<T>> P(m), Q(m);    // K X_a and K W K X_a
    Eigen::Matrix<T, -1, -1> grad(m, na);  // d K_rr / d x_a
    for (int a = 0; a < m; ++a) {
      T sum(0);
      for (int q = 0; q < na; ++q) {
        const Column9<T> k = K.col(active[q]);
        grad(a, q) = T(-2) * inner(k, g[a]) * inner(k, h[a]);
        sum += unknowns(m + 1 + q) * grad(a, q);
      }
      F(a) = sum;
      if (!J) continue;
      const Square9<T> X = symmetric_outer(g[a], h[a]);
      P[a] = times(K, X);
      Q[a] = times(KWK, X);
    }
    T total(0);
    for (int q = 0; q < na; ++q) {
      F(m + q) = K(active[q], active[q]) - s;
      total += unknowns(m + 1 + q);
    }
    F(m + na) = total - T(1);
    if (!J) return;
    J->setZero(size(), size());
    for (int a = 0; a < m; ++a)
      for (int c = a; c < m; ++c) {
        const T value = T(2) * trace_of_product(Q[a], P[c]) + same_position_term(rows, coordinates, a, c, G, g, h);
        (*J)(a, c) = value;
        (*J)(c, a) = value;
      }
    for (int a = 0; a < m; ++a)
      for (int q = 0; q < na; ++q) {
        (*J)(a, m + 1 + q) = grad(a, q);
        (*J)(m + q, a) = grad(a, q);
      }
    for (int q = 0; q < na; ++q) {
      (*J)(m + q, m) = T(-1);
      (*J)(m + na, m + 1 + q) = T(1);
    }
  }
};

}  // namespace scalcal::certify_detail
