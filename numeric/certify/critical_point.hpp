// A local optimum as a square system: the gradient of f(M) in the free chart coordinates, with
// the Hessian as its Jacobian, for the smooth criteria: f = -log det M (D; rotations held by the
// gauge) and f = tr M^-1 (A). With X_a = dM/dx_a = g h^T + h g^T (g = dh/dx_a):
//   D: df = -tr(K X_a),   d2f = tr(K X_b K X_a) - tr(K X_ab)
//   A: df = -tr(K^2 X_a), d2f = 2 tr(K^2 X_a K X_b) - tr(K^2 X_ab).
#pragma once
#include <array>

#include "numeric/certify/free_coordinates.hpp"
#include "numeric/certify/interval.hpp"
#include "numeric/certify/loops.hpp"
#include "numeric/certify/sphere_chart.hpp"

namespace scalcal::certify_detail {

template <class T>
using Square9 = Eigen::Matrix<T, 9, 9>;
template <class T>
using Column9 = Eigen::Matrix<T, 9, 1>;

// Inverse (and, when asked, log-determinant) of a symmetric positive definite matrix of any size,
// by Gauss-Jordan without pivoting: no comparisons, so it runs in interval arithmetic (the matrix
// is far from singular at a certified point).
template <class T, int N>
Eigen::Matrix<T, N, N> spd_inverse(const Eigen::Matrix<T, N, N>& M, T* log_det = nullptr) {
  const Eigen::Index n = M.rows();
  Eigen::Matrix<T, N, N == Eigen::Dynamic ? Eigen::Dynamic : 2 * N> a(n, 2 * n);
  a.leftCols(n) = M;
  a.rightCols(n) = Eigen::Matrix<T, N, N>::Identity(n, n);
  using std::log;
  if (log_det) *log_det = T(0);
  for (Eigen::Index k = 0; k < n; ++k) {
    const T p = a(k, k);
    if (log_det) *log_det += log(p);
    a.row(k) /= p;
    for (Eigen::Index r = 0; r < n; ++r)
      if (r != k) a.row(r) -= a(r, k) * a.row(k);
  }
  return a.rightCols(n);
}

template <class T>
Square9<T> spd_inverse(const Square9<T>& M, T& log_det) {
  return spd_inverse(M, &log_det);
}

// M = sum h h^T at full chart coordinates z, with the rows' jets when asked for.
template <class T>
Square9<T> assemble_information(const SphereChart& chart, const Eigen::Matrix<T, -1, 1>& z,
                                std::vector<std::array<Jet2<T>, 9>>* rows = nullptr) {
  Square9<T> M = Square9<T>::Zero();
  for (int i = 0; i < static_cast<int>(chart.e.size()); ++i) {
    const auto h = paper9_row(chart.position<T>(i, z(2 * i), z(2 * i + 1)));
    Column9<T> hv;
    for (int r = 0; r < 9; ++r) hv(r) = h[r].f;
    M += symmetric_outer(hv, hv) / T(2);
    if (rows) rows->push_back(h);
  }
  return M;
}

// h and g = dh/dx_a of the position that free coordinate a moves.
template <class T>
void row_derivatives(const std::vector<std::array<Jet2<T>, 9>>& rows, const FreeCoordinates& coordinates,
                     std::vector<Column9<T>>& g, std::vector<Column9<T>>& h) {
  const int m = coordinates.size();
  g.resize(m);
  h.resize(m);
  for (int a = 0; a < m; ++a) {
    const int full = coordinates.free[a], i = full / 2;
    const bool along_u = full % 2 == 0;
    for (int r = 0; r < 9; ++r) {
      h[a](r) = rows[i][r].f;
      g[a](r) = along_u ? rows[i][r].u : rows[i][r].v;
    }
  }
}

// tr(G X_ac), X_ac = d2M/dx_a dx_c: nonzero only when a and c move the same position.
template <class T>
T same_position_term(const std::vector<std::array<Jet2<T>, 9>>& rows, const FreeCoordinates& coordinates, int a, int c,
                     const Square9<T>& G, const std::vector<Column9<T>>& g, const std::vector<Column9<T>>& h) {
  const int fa = coordinates.free[a], fc = coordinates.free[c];
  if (fa / 2 != fc / 2) return T(0);
  const int i = fa / 2;
  const int kind = (fa % 2) + (fc % 2);  // 0: uu, 1: uv, 2: vv
  Column9<T> gac;
  for (int r = 0; r < 9; ++r) gac(r) = kind == 0 ? rows[i][r].uu : kind == 1 ? rows[i][r].uv : rows[i][r].vv;
  return T(2) * inner(gac, times(G, h[a])) + T(2) * inner(g[a], times(G, g[c]));
}

enum class CriticalForm { log_det, trace };

struct CriticalPointSystem {
  const SphereChart* chart;
  FreeCoordinates coordinates;
  CriticalForm form;

  int size() const { return coordinates.size(); }

  // f at the coordinates x (no derivatives): -log det M or tr K.
  template <class T>
  T objective(const Eigen::Matrix<T, -1, 1>& x) const {
    T log_det;
    const Square9<T> K = spd_inverse(assemble_information(*chart, coordinates.full(x)), log_det);
    return form == CriticalForm::log_det ? T(-log_det) : T(K.trace());
  }

  template <class T>
  void eval(const Eigen::Matrix<T, -1, 1>& x, Eigen::Matrix<T, -1, 1>& F, Eigen::Matrix<T, -1, -1>* J) const {
    std::vector<std::array<Jet2<T>, 9>> rows;
    T log_det;
    const Square9<T> K = spd_inverse(assemble_information(*chart, coordinates.full(x), &rows), log_det);
    const Square9<T> K2 = times(K, K);
    const Square9<T> G = form == CriticalForm::log_det ? Square9<T>(-K) : Square9<T>(-K2);
    const int m = coordinates.size();
    F.resize(m);
    std::vector<Column9<T>> g, h;
    row_derivatives(rows, coordinates, g, h);
    std::vector<Square9<T>> P(m), Q(m);  // K X_a, and K^2 X_a for A
    for (int a = 0; a < m; ++a) {
      F(a) = T(2) * inner(g[a], times(G, h[a]));
      if (!J) continue;
      const Square9<T> X = symmetric_outer(g[a], h[a]);
      P[a] = times(K, X);
      if (form == CriticalForm::trace) Q[a] = times(K2, X);
    }
    if (!J) return;
    J->resize(m, m);
    for (int a = 0; a < m; ++a)
      for (int c = a; c < m; ++c) {
        const T value =
            (form == CriticalForm::log_det ? trace_of_product(P[c], P[a]) : T(T(2) * trace_of_product(Q[a], P[c]))) +
            same_position_term(rows, coordinates, a, c, G, g, h);
        (*J)(a, c) = value;
        (*J)(c, a) = value;
      }
  }
};

}  // namespace scalcal::certify_detail
