/* The pose means as the estimator sees them, the meter of an estimate, and the layout's condition
 * (fit_internal.h). */
#include <string.h>

#include "fit_internal.h"

void sc_problem_mean(const sc_problem* q, uint32_t i, scalcal_real y[3]) {
  scalcal_real m[3];
  if (q->started) {
    scalcal_pose_mean_relative(q->set, i, m);
    m[0] -= q->start.offset[0], m[1] -= q->start.offset[1], m[2] -= q->start.offset[2];
    sc_mul3v(q->start.matrix, m, y);
  } else {
    scalcal_pose_mean(q->set, i, y);
  }
}

scalcal_real sc_problem_weight(const sc_problem* q, uint32_t i) {
  return q->weight_by_samples ? (scalcal_real)q->set->poses[i].count : 1;
}

scalcal_real sc_median_ratio(const sc_problem* q) {
  /* The element of rank n/2 (0-based) of the sorted ratios, found without storing them: the value
   * with fewer than n/2 + 1 below it and at least n/2 + 1 at or below it. */
  const uint32_t n = q->set->count, want = n / 2;
  uint32_t i, j;
  for (i = 0; i < n; ++i) {
    scalcal_real yi[3], ri;
    uint32_t below = 0, at = 0;
    sc_problem_mean(q, i, yi);
    ri = sc_norm3(yi) / q->magnitude;
    for (j = 0; j < n; ++j) {
      scalcal_real yj[3], rj;
      sc_problem_mean(q, j, yj);
      rj = sc_norm3(yj) / q->magnitude;
      if (rj < ri) ++below;
      if (rj <= ri) ++at;
    }
    if (below <= want && want < at) return ri;
  }
  return 0; /* not reached for finite ratios */
}

void sc_meter_of(const sc_problem* q, const scalcal_real* X, sc_meter* m) {
  static const int pairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  int k, r;
  memset(m, 0, sizeof *m);
  for (k = 0; k < 3; ++k) {
    m->bias[k] = X[k] * q->magnitude;
    m->gain[k] = 1 + (q->p >= 6 ? X[3 + k] : 0);
  }
  if (q->p >= 9)
    for (k = 0; k < 3; ++k)
      m->phi[pairs[k][0] * 3 + pairs[k][1]] = m->phi[pairs[k][1] * 3 + pairs[k][0]] = X[6 + k] / 2;
  for (r = 0; r < 3; ++r) {
    scalcal_real off = 0;
    for (k = 0; k < 3; ++k)
      if (k != r) off += m->phi[r * 3 + k] * m->phi[r * 3 + k];
    m->phi[r * 3 + r] = SC_SQRT(1 - off); /* NaN beyond the model's reach: the residual says so */
  }
  for (k = 0; k < 9; ++k) m->G[k] = m->gain[k / 3] * m->phi[k];
  m->valid = sc_inverse3(m->G, m->Ginv) != 0 && sc_finite(m->Ginv[0]);
}

scalcal_real sc_compensate(const sc_problem* q, const sc_meter* m, uint32_t i, scalcal_real c[3]) {
  scalcal_real y[3];
  sc_problem_mean(q, i, y);
  y[0] -= m->bias[0], y[1] -= m->bias[1], y[2] -= m->bias[2];
  sc_mul3v(m->Ginv, y, c);
  return sc_norm3(c);
}

/* The condition of H^T H (unit weights) at directions e_i, from the eigenvalues: lambda_min is known
 * to about eps lambda_max, so below max(N, P) eps lambda_max the layout is not of full rank in this
 * precision (infinity). */
static scalcal_real condition_of(const scalcal_real* info, int p, uint32_t n) {
  scalcal_real values[SC_P];
  const scalcal_real nmax = (scalcal_real)(n > (uint32_t)p ? n : (uint32_t)p);
  sc_eigen_symmetric(p, info, values, 0);
  if (!(values[0] > nmax * SCALCAL_EPSILON * values[p - 1])) return (scalcal_real)INFINITY;
  return values[p - 1] / values[0];
}

/* The columns judged: the model's P, and for bias3 with a gain the start estimated, a constant
 * one (its derivative: a common gain moves every residual alike). axis6 and paper9 carry the common
 * gain already (x^2 + y^2 + z^2 = 1 is in their span). */
static int judged_columns(int p, int started) { return p == 3 && started ? 4 : p; }

static void add_direction(scalcal_real* info, int p, scalcal_real e[3]) {
  scalcal_real h[SC_P];
  const scalcal_real norm = sc_norm3(e);
  int r, c;
  e[0] /= norm, e[1] /= norm, e[2] /= norm;
  sc_row(e, h);
  if (p == 4) h[3] = 1;
  for (r = 0; r < p; ++r)
    for (c = 0; c < p; ++c) info[r * p + c] += h[r] * h[c];
}

scalcal_real sc_layout_condition(const sc_problem* q, int p, const sc_correction* through) {
  scalcal_real info[SC_P * SC_P];
  uint32_t i;
  p = judged_columns(p, through || q->started);
  memset(info, 0, sizeof info);
  for (i = 0; i < q->set->count; ++i) {
    scalcal_real m[3], e[3];
    if (through) {
      scalcal_pose_mean_relative(q->set, i, m);
      m[0] -= through->offset[0], m[1] -= through->offset[1], m[2] -= through->offset[2];
      sc_mul3v(through->matrix, m, e);
    } else {
      sc_problem_mean(q, i, e);
    }
    add_direction(info, p, e);
  }
  return condition_of(info, p, q->set->count);
}

scalcal_real sc_fitted_condition(const sc_problem* q, const scalcal_real* X) {
  scalcal_real info[SC_P * SC_P], c[3];
  const int p = judged_columns(q->p, q->started);
  sc_meter m;
  uint32_t i;
  memset(info, 0, sizeof info);
  sc_meter_of(q, X, &m);
  for (i = 0; i < q->set->count; ++i) {
    sc_compensate(q, &m, i, c);
    add_direction(info, p, c);
  }
  return condition_of(info, p, q->set->count);
}
