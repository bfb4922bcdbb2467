// Newton's method on a system of first-order conditions in MPFR, shared by every form of the polish:
// least-squares steps, because symmetries (rotations, families of optimal programs) make the
// Jacobian singular. Compiled once (newton_least_squares.cpp).
#pragma once
#include <functional>

#include "numeric/polish/real.hpp"

namespace scalcal::polish_detail {

// Newton on residual(z) = 0 from z (updated in place) until the 2-norm is at most 10^-(P+10) or
// max_iterations Jacobians have been formed; the Jacobian by central differences with step
// 10^-(P+15). Steps are minimum-norm least-squares solutions (rank cut at 1e-25), or, when
// `regularised`, Levenberg-Marquardt steps (J^T J + |F|^2 I) s = -J^T F: where the solutions form a
// manifold, the Jacobian near it has singular values of the order of the distance to it, which a
// fixed rank cut keeps and divides by; the |F|^2 shift keeps those steps small and is still
// quadratically convergent under a local error bound (Yamashita & Fukushima 2001). A regularised run
// also stops when a step fails to halve |F|: from a double optimum Newton gains far more per step,
// so slower progress means the conditions do not fit. Returns the final norm; `iterations` counts
// Jacobians.
Real newton_least_squares(const std::function<VecX(const VecX&)>& residual, VecX& z, int P, int max_iterations,
                          int& iterations, bool regularised = false);

// The residual at which all P digits are claimed: 10^-(P+10).
Real converged_residual(int P);

// A residual r moves the value by O(r) at most: the digits it leaves untouched, at most P.
int digits_left_by(const Real& residual, int P);

}  // namespace scalcal::polish_detail
