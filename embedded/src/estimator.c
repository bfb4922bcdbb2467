/* The estimator (the host's damped_gauss_newton, numeric/calibration/model_calibration.cpp): from
 * X = 0, the paper's step (eq. 6: the residual J = |c| / |I| - 1 fitted by h(eta) . dX) with a
 * halving line search on sum w J^2; where it no longer lowers the residual, Gauss-Newton with the
 * exact derivative of J takes over. A step that would take a parameter to 0.5 or beyond is refused. */
#include <string.h>

#include "fit_internal.h"

/* sum w J^2 at X (infinity when the meter cannot be inverted or a residual is not finite). */
static scalcal_real cost_at(const sc_problem* q, const scalcal_real* X) {
  sc_meter m;
  scalcal_real cost = 0, c[3];
  uint32_t i;
  sc_meter_of(q, X, &m);
  if (!m.valid) return (scalcal_real)INFINITY;
  for (i = 0; i < q->set->count; ++i) {
    const scalcal_real norm = sc_compensate(q, &m, i, c);
    const scalcal_real J = sc_cell_modulus(q, &m, i, c, norm) / q->magnitude - 1;
    cost += sc_problem_weight(q, i) * J * J;
  }
  return sc_finite(cost) ? cost : (scalcal_real)INFINITY;
}

/* dJ_i/dX for the P parameters, analytically: J = |G^-1 (y - X_b |I|)| / |I| - 1. */
static void derivative(const sc_problem* q, const sc_meter* m, const scalcal_real c[3], scalcal_real norm,
                       scalcal_real* d) {
  static const int pairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  const scalcal_real M = q->magnitude;
  scalcal_real u[3], v[3], phic[3];
  int k;
  for (k = 0; k < 3; ++k) u[k] = c[k] / norm;
  for (k = 0; k < 3; ++k) v[k] = u[0] * m->Ginv[k] + u[1] * m->Ginv[3 + k] + u[2] * m->Ginv[6 + k]; /* u^T G^-1 */
  sc_mul3v(m->phi, c, phic);
  for (k = 0; k < 3; ++k) d[k] = -v[k];
  if (q->p >= 6)
    for (k = 0; k < 3; ++k) d[3 + k] = -v[k] * phic[k] / M;
  if (q->p >= 9)
    for (k = 0; k < 3; ++k) {
      /* dPhi/dgamma: 1/2 at (a, b) and (b, a), -phi_ab / (2 Phi_aa) at (a, a), likewise at (b, b). */
      const int a = pairs[k][0], b = pairs[k][1];
      const scalcal_real sa = v[a] * m->gain[a], sb = v[b] * m->gain[b], phi = m->phi[a * 3 + b];
      const scalcal_real t =
          sa * c[b] + sb * c[a] - (phi / m->phi[a * 3 + a]) * sa * c[a] - (phi / m->phi[b * 3 + b]) * sb * c[b];
      d[6 + k] = -t / (2 * M);
    }
}

/* Tumbling: dJ_i/dX by central differences (the host's way), since a cell's mean modulus depends on
 * X through its spread too (tr(A S A^T), A = G^-1 T), which the analytic derivative of |c| leaves
 * out: 3 % of the main term in a cell of 0.25 rad, enough to stop Gauss-Newton short of the minimum.
 * The step: eps^(1/3) relative to 1 (the parameters are of order 0.01-0.1). */
#if defined(SCALCAL_LONG_DOUBLE) || defined(SCALCAL_DOUBLE)
#define SC_DIFFERENCE_STEP ((scalcal_real)6e-6)
#else
#define SC_DIFFERENCE_STEP ((scalcal_real)5e-3)
#endif
static void cell_derivative(const sc_problem* q, const scalcal_real* X, uint32_t i, scalcal_real* d) {
  scalcal_real Y[SC_P], c[3];
  sc_meter m;
  int r, side;
  memcpy(Y, X, sizeof Y);
  for (r = 0; r < q->p; ++r) {
    scalcal_real J[2];
    for (side = 0; side < 2; ++side) {
      Y[r] = X[r] + (side ? SC_DIFFERENCE_STEP : -SC_DIFFERENCE_STEP);
      sc_meter_of(q, Y, &m);
      J[side] = sc_cell_modulus(q, &m, i, c, sc_compensate(q, &m, i, c)) / q->magnitude;
    }
    Y[r] = X[r];
    d[r] = (J[1] - J[0]) / (2 * SC_DIFFERENCE_STEP);
  }
}

/* The step: the paper's (exact = 0) or Gauss-Newton's (exact = 1); *in_se (may be null) its largest
 * entry in residual-based standard errors, sqrt(cost / (N - P) (H^T W H)^-1_rr) (infinity when
 * N = P). 0 when the normal matrix is not positive definite. */
static int step_at(const sc_problem* q, const scalcal_real* X, int exact, scalcal_real* dX, scalcal_real* in_se) {
  const int p = q->p;
  scalcal_real info[SC_P * SC_P], rhs[SC_P], h[SC_P], c[3], cost = 0;
  sc_meter m;
  uint32_t i;
  int r, s;
  sc_meter_of(q, X, &m);
  if (!m.valid) return 0;
  memset(info, 0, sizeof info);
  memset(rhs, 0, sizeof rhs);
  for (i = 0; i < q->set->count; ++i) {
    const scalcal_real norm = sc_compensate(q, &m, i, c), w = sc_problem_weight(q, i);
    const scalcal_real J = sc_cell_modulus(q, &m, i, c, norm) / q->magnitude - 1;
    if (exact) {
      if (q->tumbling)
        cell_derivative(q, X, i, h);
      else
        derivative(q, &m, c, norm, h);
      for (r = 0; r < p; ++r) h[r] = -h[r]; /* J ~ -D dX: the same sign as the paper's rows */
    } else {
      const scalcal_real e[3] = {c[0] / norm, c[1] / norm, c[2] / norm};
      sc_row(e, h);
    }
    cost += w * J * J;
    for (r = 0; r < p; ++r) {
      rhs[r] += w * J * h[r];
      for (s = 0; s < p; ++s) info[r * p + s] += w * h[r] * h[s];
    }
  }
  if (!sc_cholesky(p, info)) return 0;
  sc_cholesky_solve(p, info, rhs, dX);
  for (r = 0; r < p; ++r)
    if (!sc_finite(dX[r])) return 0;
  if (in_se) {
    *in_se = 0;
    if (q->set->count <= (uint32_t)p || !(cost > 0)) *in_se = (scalcal_real)INFINITY;
    for (r = 0; r < p && *in_se < (scalcal_real)INFINITY; ++r) {
      scalcal_real e[SC_P], x[SC_P], se;
      for (s = 0; s < p; ++s) e[s] = s == r ? 1 : 0;
      sc_cholesky_solve(p, info, e, x);
      se = SC_SQRT(cost / (scalcal_real)(q->set->count - (uint32_t)p) * x[r]);
      if (SC_FABS(dX[r]) / se > *in_se) *in_se = SC_FABS(dX[r]) / se;
    }
  }
  return 1;
}

static scalcal_real max_abs(int p, const scalcal_real* v, scalcal_real t) {
  scalcal_real m = 0;
  int k;
  for (k = 0; k < p; ++k)
    if (SC_FABS(t * v[k]) > m) m = SC_FABS(t * v[k]);
  return m;
}

/* The halving line search: 1 with X and cost updated when a step lowers the residual. */
static int line_search(const sc_problem* q, scalcal_real* X, const scalcal_real* dX, scalcal_real* cost,
                       scalcal_real* t_taken, int* edge) {
  scalcal_real t = 1, next[SC_P];
  int halvings, k;
  for (halvings = 0; halvings < 30; ++halvings, t /= 2) {
    scalcal_real c;
    for (k = 0; k < q->p; ++k) next[k] = X[k] + t * dX[k];
    if (max_abs(q->p, next, 1) >= SC_MODEL_EDGE) {
      *edge = 1;
      continue;
    }
    c = cost_at(q, next);
    if (sc_finite(c) && c <= *cost) {
      memcpy(X, next, sizeof(scalcal_real) * (unsigned)q->p);
      *cost = c;
      *t_taken = t;
      return 1;
    }
  }
  return 0;
}

void sc_estimate(const sc_problem* q, int max_iterations, scalcal_real* X, scalcal_fit_report* report) {
  scalcal_real cost, dX[SC_P];
  int exact = 0, it;
  memset(X, 0, sizeof(scalcal_real) * SC_P);
  cost = cost_at(q, X);
  report->termination = SCALCAL_FIT_ITERATION_LIMIT;
  for (it = 1; it <= max_iterations; ++it) {
    scalcal_real t = 1, step;
    int accepted = 0, edge = 0;
    if (!sc_finite(cost)) {
      report->termination = SCALCAL_FIT_NOT_FINITE;
      break;
    }
    scalcal_real in_se = (scalcal_real)INFINITY;
    if (step_at(q, X, exact, dX, SC_STEP_IN_STANDARD_ERRORS > 0 ? &in_se : 0)) {
      scalcal_real before[SC_P], cost_before = cost;
      memcpy(before, X, sizeof before);
      accepted = line_search(q, X, dX, &cost, &t, &edge);
      if (accepted && t < SC_PAPER_STEP_MIN) { /* float: a rounding-level step, not a descent */
        memcpy(X, before, sizeof before);
        cost = cost_before;
        accepted = 0;
      }
    } else {
      memset(dX, 0, sizeof dX), edge = 0, dX[0] = (scalcal_real)INFINITY;
    }
    step = max_abs(q->p, dX, accepted ? t : 1);
    /* Converged: a step below the tolerance, or none that descends while the full step is below the
     * precision's floor (a halved step of a direction that is not small is not convergence); in
     * float also a full step below a thousandth of every parameter's standard error. */
    if ((step < SC_TOLERANCE && max_abs(q->p, dX, 1) < SC_TOLERANCE_FLOOR) ||
        (!accepted && step < SC_TOLERANCE_FLOOR) || in_se < SC_STEP_IN_STANDARD_ERRORS) {
      report->termination = SCALCAL_FIT_CONVERGED;
      break;
    }
    if (!accepted && !exact) {
      exact = 1; /* the paper's step has done what it can: the exact derivative from here */
      continue;
    }
    if (!accepted) {
      report->termination = edge ? SCALCAL_FIT_MODEL_EDGE : SCALCAL_FIT_NO_DESCENT;
      break;
    }
  }
  report->iterations = it > max_iterations ? max_iterations : it;
}
