// The lower triangle of a symmetric P x P matrix as Q = P(P+1)/2 pairs, and the second-order form on
// those pairs that the structured Hessian and the lifted S problem both need.
#pragma once
#include <Eigen/Core>

namespace scalcal {

// The index of the pair (a, b), either order, when the pairs a >= b are laid out row by row: a(a+1)/2 + b.
constexpr int symmetric_pair(int a, int b) { return a >= b ? a * (a + 1) / 2 + b : b * (b + 1) / 2 + a; }

// F(q1, q2) = tr(S1 X S2 Y) + tr(S1 Y S2 X) for the pairs q1 = (a, b), q2 = (c, d), where
// S_ab = e_a e_b^T + e_b e_a^T (e_a e_a^T when a = b): the coupling d/dm_q1 d/dm_q2 of a function of a
// symmetric matrix whose second derivative is tr(X dM Y dM) + tr(Y dM X dM). Term by term,
// tr(e_p e_s^T X e_u e_v^T Y) = X(s, u) Y(v, p).
template <int P>
Eigen::Matrix<double, P*(P + 1) / 2, P*(P + 1) / 2> pair_trace_form(const Eigen::Matrix<double, P, P>& X,
                                                                    const Eigen::Matrix<double, P, P>& Y) {
  struct Term {
    int p, s;
  };
  auto terms = [](int a, int b, Term* out) {
    out[0] = {a, b};
    if (a == b) return 1;
    out[1] = {b, a};
    return 2;
  };
  Eigen::Matrix<double, P*(P + 1) / 2, P*(P + 1) / 2> F;
  for (int a = 0; a < P; ++a)
    for (int b = 0; b <= a; ++b)
      for (int c = 0; c < P; ++c)
        for (int d = 0; d <= c; ++d) {
          Term t1[2], t2[2];
          const int k1 = terms(a, b, t1), k2 = terms(c, d, t2);
          double sum = 0;
          for (int u = 0; u < k1; ++u)
            for (int v = 0; v < k2; ++v)
              sum += X(t1[u].s, t2[v].p) * Y(t2[v].s, t1[u].p) + Y(t1[u].s, t2[v].p) * X(t2[v].s, t1[u].p);
          F(symmetric_pair(a, b), symmetric_pair(c, d)) = sum;
        }
  return F;
}

}  // namespace scalcal
