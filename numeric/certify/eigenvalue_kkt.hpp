// A local optimum of E (the smallest eigenvalue lambda of M = H^T H, of multiplicity m at the
// optimum) as a square system. With Q = [U V] the computed eigenvectors (U for the cluster),
// S = A22^-1 A21 for A = Q^T (M - lambda I) Q and W = U - V S, the cluster sits at lambda exactly
// when the Schur complement R = W^T (M - lambda I) W is 0; locally lambda_min(M) >= lambda iff R is
// positive semidefinite (A22 positive definite). The KKT system of max lambda subject to R >= 0 is
//   <Omega, dR/dx_a> = 0,  <Omega, dR/dlambda> + 1 = 0,  R = 0   (Omega symmetric m x m)
// with dR = W^T dA W and d2R_ab = W^T A_ab W - Y_b^T A22^-1 Y_a - Y_a^T A22^-1 Y_b, Y = V^T dA W.
// Unknowns: x, lambda, then the upper triangle of Omega; off-diagonal rows are doubled so that the
// Jacobian is symmetric: its leading block is the Hessian of <Omega, R> in (x, lambda).
#pragma once
#include <vector>

#include "numeric/certify/critical_point.hpp"

namespace scalcal::certify_detail {

template <class T>
using Dense = Eigen::Matrix<T, -1, -1>;

struct EigenvalueKktSystem {
  const SphereChart* chart;
  FreeCoordinates coordinates;        // the chart coordinates; lambda and Omega follow them
  int multiplicity = 1;               // m
  Eigen::Matrix<double, 9, 9> basis;  // Q: columns 0..m-1 span the computed cluster

  int free_size() const { return coordinates.size(); }
  int pairs() const { return multiplicity * (multiplicity + 1) / 2; }
  int size() const { return free_size() + 1 + pairs(); }

  // The pieces every certificate check needs, at one point (or over one box).
  template <class T>
  struct Parts {
    Dense<T> omega, A22;  // Omega (m x m) and the complementary block
  };

  template <class T>
  void eval(const Eigen::Matrix<T, -1, 1>& unknowns, Eigen::Matrix<T, -1, 1>& F, Eigen::Matrix<T, -1, -1>* J,
            Parts<T>* parts = nullptr) const {
    const int n = free_size(), m = multiplicity, c = 9 - m;
    const T lambda = unknowns(n);
    std::vector<std::array<Jet2<T>, 9>> rows;
    const Square9<T> M =
        assemble_information(*chart, coordinates.full(Eigen::Matrix<T, -1, 1>(unknowns.head(n))), &rows);
    const Dense<T> Q = basis.cast<T>();
    const Dense<T> U = Q.leftCols(m), V = Q.rightCols(c);
    Square9<T> shifted = M;
    for (int i = 0; i < 9; ++i) shifted(i, i) -= lambda;
    const Dense<T> MV = times(shifted, V);
    const Dense<T> A22 = times(Dense<T>(V.transpose()), MV);
    const Dense<T> A22inv = spd_inverse(A22);
    const Dense<T> S = times(A22inv, Dense<T>(times(Dense<T>(MV.transpose()), U)));
    const Dense<T> W = U - times(V, S);
    const Dense<T> R = times(Dense<T>(W.transpose()), Dense<T>(times(shifted, W)));
    const Dense<T> WtW = times(Dense<T>(W.transpose()), W);
    Dense<T> omega(m, m);
    for (int i = 0, q = n + 1; i < m; ++i)
      for (int j = i; j < m; ++j, ++q) {
        omega(i, j) = unknowns(q);
        if (j != i) omega(j, i) = unknowns(q);  // x = x on an mpfi_float resets its precision, i.e. to NaN
      }
    if (parts) *parts = Parts<T>{omega, A22};
    // <Omega, B> as a function of the unknowns' upper triangle: B_ii, and B_ij + B_ji off the diagonal.
    auto weight = [](const Dense<T>& B, int i, int j) { return i == j ? B(i, i) : T(B(i, j) + B(j, i)); };
    auto pairing = [&](const Dense<T>& B) { return trace_of_product(omega, B); };

    std::vector<Column9<T>> g, h;
    row_derivatives(rows, coordinates, g, h);
    const Dense<T> Wt = W.transpose(), Vt = V.transpose();
    std::vector<Dense<T>> dR(n + 1), Y(n + 1);
    for (int a = 0; a < n; ++a) {
      const Eigen::Matrix<T, -1, 1> p = times(Wt, g[a]), q = times(Wt, h[a]);
      const Eigen::Matrix<T, -1, 1> vg = times(Vt, g[a]), vh = times(Vt, h[a]);
      dR[a] = times(p, Dense<T>(q.transpose())) + times(q, Dense<T>(p.transpose()));
      Y[a] = times(vg, Dense<T>(q.transpose())) + times(vh, Dense<T>(p.transpose()));
    }
    dR[n] = -WtW;
    Y[n] = -times(Vt, W);

    F.resize(size());
    for (int t = 0; t <= n; ++t) F(t) = pairing(dR[t]);
    F(n) += T(1);
    for (int i = 0, q = n + 1; i < m; ++i)
      for (int j = i; j < m; ++j, ++q) F(q) = weight(R, i, j);
    if (!J) return;

    J->setZero(size(), size());
    const Square9<T> G = times(W, Dense<T>(times(omega, Wt)));
    std::vector<Dense<T>> AY(n + 1), YO(n + 1);  // A22^-1 Y_t and Y_t Omega
    for (int t = 0; t <= n; ++t) {
      AY[t] = times(A22inv, Y[t]);
      YO[t] = times(Y[t], omega);
    }
    for (int a = 0; a <= n; ++a)
      for (int b = a; b <= n; ++b) {
        T value = T(-2) * entrywise_inner(YO[b], AY[a]);
        if (a < n && b < n) value += same_position_term(rows, coordinates, a, b, G, g, h);
        (*J)(a, b) = value;
        (*J)(b, a) = value;
      }
    for (int t = 0; t <= n; ++t)
      for (int i = 0, q = n + 1; i < m; ++i)
        for (int j = i; j < m; ++j, ++q) (*J)(t, q) = (*J)(q, t) = weight(dR[t], i, j);
  }
};

}  // namespace scalcal::certify_detail
