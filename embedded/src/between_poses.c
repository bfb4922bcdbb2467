/* The between-pose error model of the host (numeric/calibration/between_poses.cpp): a pose's mean
 * modulus residual J_k has variance V_k = s + v0_k, v0_k = sigma_w^2 / n_k the noise within the pose
 * over its n_k samples and s = sigma_b^2 what no averaging removes (a hand-held pose is never the
 * same twice). s by restricted maximum likelihood (Fisher scoring), then the estimator's covariance
 * under it by the sandwich with the estimator's own weights.
 *
 * The host forms the n x n projection P = W - W H A^-1 H^T W (W = diag(1 / V_k), A = H^T W H, H the
 * poses' design rows h_k^T) and steps s += (J^T P P J - tr P) / tr(P P) (score over expected
 * information; the halves cancel). A device keeps no n x n matrix; the same three numbers in P x P
 * form, with q_k = h_k^T A^-1 h_k, beta = A^-1 sum_k w_k h_k J_k and B2 = sum_k w_k^2 h_k h_k^T:
 *   P J = W J - W H A^-1 H^T W J = W (J - H beta), so |P J|^2 = sum_k w_k^2 (J_k - h_k^T beta)^2;
 *   tr P = sum_k w_k - tr(A^-1 H^T W^2 H) = sum_k w_k - sum_k w_k^2 q_k;
 *   P P = W^2 - W^2 H A^-1 H^T W - W H A^-1 H^T W^2 + W H A^-1 B2 A^-1 H^T W, and by the trace's
 *   cyclic invariance tr(P P) = sum_k w_k^2 - 2 sum_k w_k^3 q_k + tr(X X), X = A^-1 B2.
 * So each step is two passes over the poses (sums, then q_k and the residuals of the weighted fit)
 * with two P x P matrices (A's Cholesky factor and X). The terms of tr P and tr(P P) are each of the
 * size of the result times n / (n - P): no cancellation beyond that. The covariance is K B K with
 * K = (H^T W0 H)^-1 (the residual-based error's) and B = sum_k w0_k^2 V_k h_k h_k^T, w0_k 1 per pose
 * or n_k. Everything at the estimate: h_k at the pose's compensated direction, J_k = |c_k| / |I| - 1. */
#include <string.h>

#include "fit_internal.h"

/* The host stops when a step moves s by at most 1e-10 of max(s, mean v0); float resolves less. */
#if defined(SCALCAL_DOUBLE) || defined(SCALCAL_LONG_DOUBLE)
#define SC_REML_TOLERANCE ((scalcal_real)1e-10)
#else
#define SC_REML_TOLERANCE ((scalcal_real)1e-5)
#endif
#define SC_REML_ITERATIONS 100

/* Pose i's design row at its compensated direction and its residual J = |c| / |I| - 1. */
static void pose_row(const sc_problem* q, const sc_meter* m, uint32_t i, scalcal_real h[SC_P], scalcal_real* J) {
  scalcal_real c[3];
  const scalcal_real norm = sc_compensate(q, m, i, c);
  const scalcal_real e[3] = {c[0] / norm, c[1] / norm, c[2] / norm};
  sc_row(e, h);
  *J = norm / q->magnitude - 1;
}

/* s plus one Fisher step (NaN when A is not positive definite); a and x are P x P scratch. */
static scalcal_real fisher_step(const sc_problem* q, const sc_meter* m, scalcal_real within, scalcal_real s,
                                scalcal_real* a, scalcal_real* x) {
  const int p = q->p;
  scalcal_real h[SC_P], g[SC_P], beta[SC_P], y[SC_P], J, sw = 0, sw2 = 0, pj = 0, t2 = 0, t3 = 0, xx = 0;
  uint32_t i;
  int r, c;
  memset(a, 0, sizeof(scalcal_real) * (unsigned)(p * p));
  memset(x, 0, sizeof(scalcal_real) * (unsigned)(p * p));
  memset(g, 0, sizeof g);
  for (i = 0; i < q->set->count; ++i) {
    const scalcal_real w = 1 / (within / (scalcal_real)q->set->poses[i].count + s);
    pose_row(q, m, i, h, &J);
    sw += w, sw2 += w * w;
    for (r = 0; r < p; ++r) {
      g[r] += w * h[r] * J;
      for (c = 0; c < p; ++c) a[r * p + c] += w * h[r] * h[c], x[r * p + c] += w * w * h[r] * h[c];
    }
  }
  if (!sc_cholesky(p, a)) return (scalcal_real)NAN;
  sc_cholesky_solve(p, a, g, beta);
  for (r = 0; r < p; ++r) sc_cholesky_solve(p, a, x + r * p, x + r * p); /* rows of X^T = B2 A^-1 */
  for (r = 0; r < p; ++r)
    for (c = 0; c < p; ++c) xx += x[r * p + c] * x[c * p + r];
  for (i = 0; i < q->set->count; ++i) {
    const scalcal_real w = 1 / (within / (scalcal_real)q->set->poses[i].count + s);
    scalcal_real qk = 0, e;
    pose_row(q, m, i, h, &J);
    sc_cholesky_solve(p, a, h, y);
    e = J;
    for (r = 0; r < p; ++r) qk += h[r] * y[r], e -= h[r] * beta[r];
    pj += w * w * e * e, t2 += w * w * qk, t3 += w * w * w * qk;
  }
  return s + (pj - (sw - t2)) / (sw2 - 2 * t3 + xx);
}

int sc_between_poses(const sc_problem* q, const sc_meter* m, scalcal_real within, const scalcal_real* K,
                     scalcal_real* a, scalcal_real* x, sc_between* out) {
  const int p = q->p;
  const uint32_t n = q->set->count;
  scalcal_real h[SC_P], J, ss = 0, v0 = 0, s;
  uint32_t i;
  int r, c;
  for (i = 0; i < n; ++i) {
    pose_row(q, m, i, h, &J);
    ss += J * J;
    v0 += within / (scalcal_real)q->set->poses[i].count;
  }
  v0 /= (scalcal_real)n; /* the mean of v0_k: the host's start and its scale of convergence */
  s = ss / (scalcal_real)(n - (uint32_t)p) - v0;
  if (!(s > 0)) s = 0;
  out->converged = 0;
  for (out->iterations = 1; out->iterations <= SC_REML_ITERATIONS; ++out->iterations) {
    scalcal_real next = fisher_step(q, m, within, s, a, x);
    int settled;
    if (!sc_finite(next)) return 0;
    if (!(next > 0)) next = 0;
    settled = SC_FABS(next - s) <= SC_REML_TOLERANCE * (next > v0 ? next : v0) || (next == 0 && s == 0);
    s = next;
    if (settled) {
      out->converged = 1;
      break;
    }
  }
  out->between = s;
  /* The sandwich: B into x, K B into a, K B K into x. */
  memset(x, 0, sizeof(scalcal_real) * (unsigned)(p * p));
  for (i = 0; i < n; ++i) {
    const scalcal_real w0 = sc_problem_weight(q, i);
    const scalcal_real v = w0 * w0 * (within / (scalcal_real)q->set->poses[i].count + s);
    pose_row(q, m, i, h, &J);
    for (r = 0; r < p; ++r)
      for (c = 0; c < p; ++c) x[r * p + c] += v * h[r] * h[c];
  }
  sc_mul(p, K, x, a);
  sc_mul(p, a, K, x);
  return 1;
}
