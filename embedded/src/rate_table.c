/* scalcal_fit_rate_table (scalcal/rate_table.h): the host's rate-table calibration
 * (numeric/gyro/rate_segments.cpp, known_modulus.cpp, grouped_least_squares.cpp) on a pose set:
 * the rests found as the host finds them, the start, the model the directions carry, and the
 * grouped Levenberg-Marquardt with its variance components, step for step. */
#include <string.h>

#include "internal.h"
#include "scalcal/rate_table.h"

#define RT_SIGMAS ((scalcal_real)30)    /* the host's kRestSigmas */
#define RT_CARRY ((scalcal_real)1e4)    /* the host's kCarryCondition */
#define RT_TINY ((scalcal_real)FLT_MIN) /* the host's 1e-300 floors, in either precision */
#define RT_MATRIX_CONDITION ((scalcal_real)100)

void scalcal_rate_table_options_default(scalcal_rate_table_options* o) {
  memset(o, 0, sizeof *o);
  o->model = SCALCAL_MODEL_AUTO;
  o->rate = 1;
  o->max_iterations = 100;
}

/* One pose: its mean relative to the set's origin and one sample's standard deviation per axis. */
static void pose_stats(const scalcal_pose_set* set, uint32_t i, scalcal_real mean[3], scalcal_real sd[3]) {
  const scalcal_pose* p = &set->poses[i];
  const scalcal_real d = (scalcal_real)(p->count > 1 ? p->count - 1 : 1);
  int c;
  scalcal_pose_mean_relative(set, i, mean);
  for (c = 0; c < 3; ++c) sd[c] = SC_SQRT(p->scatter[c] / d);
}

static int coincide(const scalcal_pose_set* set, uint32_t a, uint32_t b) {
  scalcal_real ma[3], sa[3], mb[3], sb[3];
  const scalcal_real na = (scalcal_real)set->poses[a].count, nb = (scalcal_real)set->poses[b].count;
  int c;
  pose_stats(set, a, ma, sa);
  pose_stats(set, b, mb, sb);
  for (c = 0; c < 3; ++c) {
    const scalcal_real se = SC_SQRT(sa[c] * sa[c] / na + sb[c] * sb[c] / nb);
    const scalcal_real floor = (scalcal_real)0.5 * (sa[c] < sb[c] ? sa[c] : sb[c]);
    if (SC_FABS(ma[c] - mb[c]) > RT_SIGMAS * se + floor) return 0;
  }
  return 1;
}

static int root(int* parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

/* The host's segment_rate_log: union-find over coinciding poses, the largest group of at least two
 * (ties to the earliest root) are the rests. */
static void split(const scalcal_pose_set* set, uint8_t* rest) {
  int parent[SCALCAL_MAX_POSES], size[SCALCAL_MAX_POSES];
  const int n = (int)set->count;
  int i, j, best = -1;
  for (i = 0; i < n; ++i) parent[i] = i, size[i] = 0;
  for (i = 0; i < n; ++i)
    for (j = i + 1; j < n; ++j)
      if (coincide(set, (uint32_t)i, (uint32_t)j)) parent[root(parent, i)] = root(parent, j);
  for (i = 0; i < n; ++i) ++size[root(parent, i)];
  for (i = 0; i < n; ++i)
    if (size[i] >= 2 && (best < 0 || size[i] > size[best])) best = i;
  for (i = 0; i < n; ++i) rest[i] = (uint8_t)(best >= 0 && root(parent, i) == best);
}

typedef struct {
  const scalcal_pose_set* set;
  const uint8_t* rest;
  int free;                 /* 9 paper9, 6 axis6, 4 bias3 */
  uint32_t rows;            /* segments, then 3 per rest */
  scalcal_real rate, gain0; /* the start's gain: raw units per physical unit */
  scalcal_real step[9];
  scalcal_real weight[2]; /* 1 / sqrt(scale) of the segments and the rests */
} rt_problem;

/* x (o, k, gamma) of the model's free parameters p. */
static void expand(const rt_problem* q, const scalcal_real* p, scalcal_real x[9]) {
  int k;
  for (k = 0; k < 9; ++k) x[k] = 0;
  for (k = 0; k < 3; ++k) {
    x[k] = p[k];
    x[3 + k] = q->free == 4 ? p[3] : p[3 + k];
    if (q->free == 9) x[6 + k] = p[6 + k];
  }
}

/* G^-1 of x: G = diag(k) Phi(gamma), phi_kj = phi_jk = gamma / 2, unit rows (the host's Meter). */
static int inverse_meter(const scalcal_real x[9], scalcal_real Ginv[9]) {
  static const int pairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  scalcal_real phi[9], G[9];
  int k, r;
  memset(phi, 0, sizeof phi);
  for (k = 0; k < 3; ++k) phi[pairs[k][0] * 3 + pairs[k][1]] = phi[pairs[k][1] * 3 + pairs[k][0]] = x[6 + k] / 2;
  for (r = 0; r < 3; ++r) {
    scalcal_real off = 0;
    for (k = 0; k < 3; ++k)
      if (k != r) off += phi[r * 3 + k] * phi[r * 3 + k];
    phi[r * 3 + r] = SC_SQRT(1 - off);
  }
  for (k = 0; k < 9; ++k) G[k] = x[3 + k / 3] * phi[k];
  return sc_inverse3(G, Ginv) != 0;
}

/* Row `row` of the residuals in units of its predicted noise (unweighted); its group in *group. */
static scalcal_real residual(const rt_problem* q, const scalcal_real x[9], uint32_t row, int* group) {
  scalcal_real mean[3], sd[3];
  uint32_t i, seen = 0;
  const uint32_t n = q->set->count;
  for (i = 0; i < n; ++i) /* segment number `row` */
    if (!q->rest[i] && seen++ == row) {
      scalcal_real Ginv[9], y[3], c[3], noise;
      const scalcal_real count = (scalcal_real)q->set->poses[i].count;
      *group = 0;
      pose_stats(q->set, i, mean, sd);
      noise = sc_norm3(sd) / SC_SQRT(3 * (count > 1 ? count : 1));
      if (!inverse_meter(x, Ginv)) return (scalcal_real)NAN;
      y[0] = mean[0] - x[0], y[1] = mean[1] - x[1], y[2] = mean[2] - x[2];
      sc_mul3v(Ginv, y, c);
      return (sc_norm3(c) - q->rate) * q->gain0 / noise;
    }
  *group = 1;
  row -= seen;
  for (i = 0; i < n; ++i)
    if (q->rest[i] && row < 3) {
      const int c = (int)row;
      pose_stats(q->set, i, mean, sd);
      return (mean[c] - x[c]) * SC_SQRT((scalcal_real)q->set->poses[i].count) / (sd[c] > RT_TINY ? sd[c] : RT_TINY);
    } else if (q->rest[i]) {
      row -= 3;
    }
  return (scalcal_real)NAN;
}

/* One row's weighted Jacobian in the model's unknowns: central differences in the nine, mapped to the
 * model's (bias3's one gain is the sum of the three gains' columns). */
static void row_jacobian(const rt_problem* q, const scalcal_real x[9], uint32_t row, scalcal_real w, scalcal_real* J) {
  scalcal_real Jf[9];
  int a, group;
  for (a = 0; a < 9; ++a) {
    scalcal_real xa[9], xb[9];
    memcpy(xa, x, sizeof xa);
    memcpy(xb, x, sizeof xb);
    xa[a] += q->step[a];
    xb[a] -= q->step[a];
    Jf[a] = w * (residual(q, xa, row, &group) - residual(q, xb, row, &group)) / (2 * q->step[a]);
  }
  for (a = 0; a < q->free; ++a) J[a] = Jf[a];
  if (q->free == 4) J[3] = Jf[3] + Jf[4] + Jf[5];
}

/* The weighted normal equations N = J^T J, g = J^T r and cost r^T r at p (J by central differences in
 * the nine, mapped to the model's). With N null, the cost alone. */
static scalcal_real accumulate(const rt_problem* q, const scalcal_real* p, scalcal_real* N, scalcal_real* g) {
  scalcal_real x[9], cost = 0;
  uint32_t row;
  int a, b, group;
  const int P = q->free;
  expand(q, p, x);
  if (N) memset(N, 0, sizeof(scalcal_real) * (size_t)(P * P)), memset(g, 0, sizeof(scalcal_real) * (size_t)P);
  for (row = 0; row < q->rows; ++row) {
    const scalcal_real r0 = residual(q, x, row, &group);
    const scalcal_real w = q->weight[group], r = w * r0;
    cost += r * r;
    if (N) {
      scalcal_real J[SC_P];
      row_jacobian(q, x, row, w, J);
      for (a = 0; a < P; ++a) {
        g[a] += J[a] * r;
        for (b = 0; b < P; ++b) N[a * P + b] += J[a] * J[b];
      }
    }
  }
  return cost;
}

/* The host's minimise: Levenberg-Marquardt with Marquardt's diagonal scaling. */
static int minimise(const rt_problem* q, scalcal_real* p, int max_iterations, scalcal_termination* term) {
  scalcal_real N[SC_P * SC_P], g[SC_P], A[SC_P * SC_P], d[SC_P], step[SC_P], next[SC_P];
  scalcal_real lambda = (scalcal_real)1e-4, cost;
  const int P = q->free;
  int it, tries, k;
  cost = accumulate(q, p, N, g);
  *term = SCALCAL_FIT_ITERATION_LIMIT;
  for (it = 1; it <= max_iterations; ++it) {
    int stepped = 0;
    for (k = 0; k < P; ++k) d[k] = N[k * P + k] > RT_TINY ? N[k * P + k] : RT_TINY;
    for (tries = 0; tries < 40 && !stepped; ++tries) {
      scalcal_real cn, scaled = 0;
      memcpy(A, N, sizeof(scalcal_real) * (size_t)(P * P));
      for (k = 0; k < P; ++k) A[k * P + k] += lambda * d[k];
      if (!sc_cholesky(P, A)) {
        lambda *= 10;
        continue;
      }
      sc_cholesky_solve(P, A, g, step);
      for (k = 0; k < P; ++k) step[k] = -step[k], next[k] = p[k] + step[k], scaled += step[k] * step[k] * d[k];
      cn = accumulate(q, next, 0, 0);
      if (sc_finite(cn) && cn <= cost) {
        const int small =
            SC_SQRT(scaled) < (scalcal_real)1e-9 * (1 + SC_SQRT(cost)) || cost - cn < (scalcal_real)1e-15 * cost;
        memcpy(p, next, sizeof(scalcal_real) * (size_t)P);
        stepped = 1;
        lambda = lambda / 10 > (scalcal_real)1e-12 ? lambda / 10 : (scalcal_real)1e-12;
        cost = accumulate(q, p, N, g);
        if (small) return *term = SCALCAL_FIT_CONVERGED, it;
      } else {
        lambda *= 10;
      }
    }
    if (!stepped) return *term = SCALCAL_FIT_CONVERGED, it; /* no step lowers the misfit further */
  }
  return max_iterations;
}

/* Each group's chi-square (the unweighted residuals: against the predicted noise) and degrees of freedom at p: rows
 * less their leverage J_i^T N^-1 J_i. Ninv: the weighted normal matrix's inverse. */
static void groups_at(const rt_problem* q, const scalcal_real* p, const scalcal_real* Ninv, scalcal_real chi[2],
                      scalcal_real dof[2]) {
  scalcal_real x[9];
  uint32_t row;
  int a, b, group;
  const int P = q->free;
  expand(q, p, x);
  chi[0] = chi[1] = dof[0] = dof[1] = 0;
  for (row = 0; row < q->rows; ++row) {
    scalcal_real J[SC_P], h = 0;
    const scalcal_real r = residual(q, x, row, &group), w = q->weight[group];
    row_jacobian(q, x, row, w, J);
    for (a = 0; a < P; ++a)
      for (b = 0; b < P; ++b) h += J[a] * Ninv[a * P + b] * J[b];
    chi[group] += r * r;
    dof[group] += 1 - h;
  }
}

/* The host's gyro_information: the model's rows at the start's directions, the rests' rows on o. */
static scalcal_real carried(const scalcal_pose_set* set, const uint8_t* rest, const scalcal_real o[3], int P,
                            uint32_t segments) {
  scalcal_real M[SC_P * SC_P], values[SC_P];
  uint32_t i;
  int a, b;
  memset(M, 0, sizeof M);
  for (i = 0; i < set->count; ++i) {
    scalcal_real m[3], sd[3], h[SC_P], len;
    if (rest[i]) continue;
    pose_stats(set, i, m, sd);
    m[0] -= o[0], m[1] -= o[1], m[2] -= o[2];
    len = sc_norm3(m);
    m[0] /= len, m[1] /= len, m[2] /= len;
    sc_row(m, h);
    if (P == 4) h[3] = 1;
    for (a = 0; a < P; ++a)
      for (b = 0; b < P; ++b) M[a * P + b] += h[a] * h[b];
  }
  if (segments < set->count)
    for (a = 0; a < 3; ++a) M[a * P + a] += (scalcal_real)segments / 3;
  sc_eigen_symmetric(P, M, values, 0);
  return values[0] > (scalcal_real)1e-12 * values[P - 1] ? values[P - 1] / values[0] : (scalcal_real)INFINITY;
}

static void sort(scalcal_real* v, uint32_t n) {
  uint32_t i, j;
  for (i = 1; i < n; ++i)
    for (j = i; j > 0 && v[j - 1] > v[j]; --j) {
      const scalcal_real t = v[j];
      v[j] = v[j - 1], v[j - 1] = t;
    }
}

/* The inputs' checks: arguments, finite sums, a stream that moves most of the time. */
static scalcal_status check_inputs(const scalcal_pose_set* set, const scalcal_rate_table_options* options,
                                   const scalcal_calibration* cal) {
  uint32_t i;
  int k;
  if (!set || !options || !cal || !set->poses || set->count > SCALCAL_MAX_POSES) return SCALCAL_E_ARGUMENT;
  if (options->model != SCALCAL_MODEL_AUTO && options->model != SCALCAL_MODEL_BIAS3 &&
      options->model != SCALCAL_MODEL_AXIS6 && options->model != SCALCAL_MODEL_PAPER9)
    return SCALCAL_E_ARGUMENT;
  if (!(options->rate > 0 && sc_finite(options->rate)) || options->max_iterations < 1) return SCALCAL_E_ARGUMENT;
  for (i = 0; i < set->count; ++i) {
    if (set->poses[i].count == 0) return SCALCAL_E_NOT_FINITE;
    for (k = 0; k < 3; ++k)
      if (!sc_finite(set->poses[i].mean[k]) || !sc_finite(set->poses[i].scatter[k]) || !sc_finite(set->origin[k]))
        return SCALCAL_E_NOT_FINITE;
  }
  if ((uint64_t)set->windows_moving * 4 > (uint64_t)set->windows_judged * 3) return SCALCAL_E_MOVING;
  return SCALCAL_OK;
}

/* The split into segments and rests, and the start: o the rests' mean, one gain, the median over segments of
 * |mean - o| / rate. `values` is scratch of SCALCAL_MAX_POSES. */
static scalcal_status start_of(const scalcal_pose_set* set, const scalcal_rate_table_options* options,
                               scalcal_rate_table_report* r, scalcal_real o[3], rt_problem* q, scalcal_real* values,
                               uint32_t* total) {
  uint32_t i, n = 0, segments = 0, rests = 0;
  int k;
  split(set, r->rest);
  for (i = 0; i < set->count; ++i) {
    scalcal_real m[3], sd[3];
    *total += set->poses[i].count;
    if (!r->rest[i]) {
      ++segments;
      continue;
    }
    pose_stats(set, i, m, sd);
    for (k = 0; k < 3; ++k) o[k] += m[k];
    ++rests;
  }
  r->segments = segments, r->rests = rests;
  if (rests < 2) return SCALCAL_E_NO_RESTS;
  if (segments == 0) return SCALCAL_E_TOO_FEW_POSES;
  for (k = 0; k < 3; ++k) o[k] /= (scalcal_real)rests;
  memset(q, 0, sizeof *q);
  q->set = set, q->rest = r->rest, q->rate = options->rate, q->rows = segments + 3 * rests;
  q->weight[0] = q->weight[1] = 1;
  for (i = 0; i < set->count; ++i) {
    scalcal_real m[3], sd[3];
    if (r->rest[i]) continue;
    pose_stats(set, i, m, sd);
    m[0] -= o[0], m[1] -= o[1], m[2] -= o[2];
    values[n++] = sc_norm3(m) / options->rate;
  }
  sort(values, n);
  q->gain0 = values[n / 2];
  /* A segment under half the rate at that gain is a rest the split did not link (or the rate is wrong). */
  if (!(values[0] >= (scalcal_real)0.5 * q->gain0) || !(q->gain0 > 0)) return SCALCAL_E_MAGNITUDE;
  return SCALCAL_OK;
}

/* The model: the one asked for, or the richest of paper9, axis6, bias3 the directions carry; 0 for none. */
static int model_of(const scalcal_pose_set* set, const scalcal_rate_table_options* options,
                    scalcal_rate_table_report* r, const scalcal_real o[3]) {
  static const int kModels[3] = {9, 6, 4};
  int k;
  for (k = 0; k < 3; ++k) {
    const int want = kModels[k];
    if (options->model != SCALCAL_MODEL_AUTO &&
        want != (options->model == SCALCAL_MODEL_BIAS3 ? 4 : (int)options->model))
      continue;
    r->model = want == 4 ? SCALCAL_MODEL_BIAS3 : (scalcal_model)want;
    r->condition = carried(set, r->rest, o, want, r->segments);
    if (r->condition <= RT_CARRY) return want;
  }
  return 0;
}

/* The fit with its variance components: refit until each group's scale settles (at most 8 passes). */
static scalcal_status fit_groups(rt_problem* q, scalcal_real* p, int P, const scalcal_rate_table_options* options,
                                 scalcal_rate_table_report* r) {
  scalcal_real scale[2] = {1, 1}, chi[2], dof[2], N[SC_P * SC_P], cov[SC_P * SC_P];
  int k, pass;
  for (pass = 0; pass < 8; ++pass) {
    int settled = 1;
    r->iterations += minimise(q, p, options->max_iterations, &r->termination);
    accumulate(q, p, N, cov);
    if (!sc_spd_inverse(P, N, N)) return SCALCAL_E_NOT_IDENTIFIABLE;
    groups_at(q, p, N, chi, dof);
    for (k = 0; k < 2; ++k) {
      scalcal_real s = scale[k];
      if (dof[k] > (scalcal_real)0.5) s = chi[k] / dof[k] > 1 ? chi[k] / dof[k] : 1;
      settled = settled && SC_FABS(s / scale[k] - 1) < (scalcal_real)1e-3;
      scale[k] = s;
      q->weight[k] = 1 / SC_SQRT(s);
    }
    if (settled) break;
  }
  r->segment_scale = scale[0], r->rest_scale = scale[1], r->segment_dof = dof[0], r->rest_dof = dof[1];
  return r->termination == SCALCAL_FIT_CONVERGED ? SCALCAL_OK : SCALCAL_E_NOT_CONVERGED;
}

/* The standard errors, achieved (with the groups' scales) and predicted (without), and the scaled condition
 * of the normal matrix; x the nine parameters at p. */
static scalcal_status errors_of(rt_problem* q, const scalcal_real* p, int P, scalcal_rate_table_report* r,
                                scalcal_real x[9]) {
  scalcal_real N[SC_P * SC_P], cov[SC_P * SC_P], D[SC_P], S[SC_P * SC_P], ev[SC_P];
  int k, a, b;
  accumulate(q, p, N, cov);
  if (!sc_spd_inverse(P, N, cov)) return SCALCAL_E_NOT_IDENTIFIABLE;
  expand(q, p, x);
  for (k = 0; k < 9; ++k) {
    const int j = k < 3 ? k : k < 6 ? (P == 4 ? 3 : k) : (P == 9 ? k : -1);
    r->parameters[k] = j >= 0 ? x[k] : (scalcal_real)NAN;
    r->standard_error[k] = j >= 0 ? SC_SQRT(cov[j * P + j] > 0 ? cov[j * P + j] : 0) : (scalcal_real)NAN;
  }
  q->weight[0] = q->weight[1] = 1;
  accumulate(q, p, N, cov);
  for (a = 0; a < P; ++a) D[a] = 1 / SC_SQRT(N[a * P + a] > RT_TINY ? N[a * P + a] : RT_TINY);
  for (a = 0; a < P; ++a)
    for (b = 0; b < P; ++b) S[a * P + b] = D[a] * N[a * P + b] * D[b];
  sc_eigen_symmetric(P, S, ev, 0);
  r->normal_condition = ev[P - 1] / (ev[0] > RT_TINY ? ev[0] : RT_TINY);
  if (!sc_spd_inverse(P, N, cov)) return SCALCAL_E_NOT_IDENTIFIABLE;
  for (k = 0; k < 9; ++k) {
    const int j = k < 3 ? k : k < 6 ? (P == 4 ? 3 : k) : (P == 9 ? k : -1);
    r->predicted_std[k] = j >= 0 ? SC_SQRT(cov[j * P + j] > 0 ? cov[j * P + j] : 0) : (scalcal_real)NAN;
  }
  return SCALCAL_OK;
}

/* The calibration: physical = G^-1 (raw - o), nominal gain 1 as the host writes it; the host's noise (the
 * rests' median |sd| / sqrt(3) through the matrix's Frobenius norm / sqrt(3)). `values` is scratch. */
static scalcal_status calibration_of(const scalcal_pose_set* set, const scalcal_rate_table_options* options,
                                     const scalcal_rate_table_report* r, const scalcal_real x[9], uint32_t total,
                                     scalcal_real* values, scalcal_calibration* out) {
  scalcal_real Ginv[9], frob = 0, MtM[9], ev[3], rms = 0;
  uint32_t i, n = 0;
  int k, a, b;
  memset(out, 0, sizeof *out);
  if (!inverse_meter(x, Ginv)) return SCALCAL_E_DEGENERATE;
  out->model = r->model;
  out->magnitude = options->rate;
  out->nominal_gain = 1;
  out->nominal_gain_std = (scalcal_real)NAN;
  out->positions = r->segments;
  out->samples = total;
  for (k = 0; k < 3; ++k) {
    out->offset[k] = x[k] + set->origin[k];
    out->gain[k] = x[3 + k];
    out->scale_deviation[k] = x[3 + k] - 1;
    out->nonorthogonality[k] = x[6 + k];
    out->bias_std[k] = r->standard_error[k];
    out->gain_std[k] = out->scale_deviation_std[k] = r->standard_error[3 + k];
    out->nonorthogonality_std[k] = r->standard_error[6 + k];
  }
  for (k = 0; k < 9; ++k) out->matrix[k / 3][k % 3] = Ginv[k], frob += Ginv[k] * Ginv[k];
  for (i = 0; i < set->count; ++i) {
    scalcal_real m[3], sd[3], c[3];
    pose_stats(set, i, m, sd);
    if (r->rest[i]) {
      values[n++] = sc_norm3(sd) / SC_SQRT(3);
    } else {
      m[0] -= x[0], m[1] -= x[1], m[2] -= x[2];
      sc_mul3v(Ginv, m, c);
      rms += (sc_norm3(c) - options->rate) * (sc_norm3(c) - options->rate);
    }
  }
  sort(values, n);
  out->noise = values[n / 2] * SC_SQRT(frob) / SC_SQRT(3);
  out->residual_rms = SC_SQRT(rms / (scalcal_real)r->segments);
  for (a = 0; a < 3; ++a)
    for (b = 0; b < 3; ++b) MtM[a * 3 + b] = Ginv[a] * Ginv[b] + Ginv[3 + a] * Ginv[3 + b] + Ginv[6 + a] * Ginv[6 + b];
  sc_eigen_symmetric(3, MtM, ev, 0);
  if (!(ev[0] > 0 && ev[2] <= RT_MATRIX_CONDITION * RT_MATRIX_CONDITION * ev[0])) return SCALCAL_E_DEGENERATE;
  for (k = 0; k < 3; ++k)
    if (!sc_finite(out->offset[k]) || !sc_finite(out->gain[k]) || !sc_finite(out->nonorthogonality[k]) ||
        !sc_finite(out->matrix[k][0]) || !sc_finite(out->matrix[k][1]) || !sc_finite(out->matrix[k][2]))
      return SCALCAL_E_NOT_FINITE;
  return SCALCAL_OK;
}

scalcal_status scalcal_fit_rate_table(const scalcal_pose_set* set, const scalcal_rate_table_options* options,
                                      scalcal_calibration* cal, scalcal_rate_table_report* report) {
  scalcal_rate_table_report local;
  scalcal_rate_table_report* r = report ? report : &local;
  scalcal_real o[3] = {0, 0, 0}, values[SCALCAL_MAX_POSES], p[SC_P], x[9];
  scalcal_calibration out;
  rt_problem q;
  uint32_t total = 0;
  int k, P;
  scalcal_status status;
  memset(r, 0, sizeof *r);
  if ((status = check_inputs(set, options, cal)) != SCALCAL_OK) return status;
  if ((status = start_of(set, options, r, o, &q, values, &total)) != SCALCAL_OK) return status;
  P = model_of(set, options, r, o);
  if (P == 0) return SCALCAL_E_NOT_IDENTIFIABLE;
  if (r->segments + 3 < (uint32_t)P) return SCALCAL_E_TOO_FEW_POSES;
  q.free = P;
  for (k = 0; k < 3; ++k) {
    q.step[k] = (scalcal_real)1e-6 * q.gain0 * options->rate;
    q.step[3 + k] = (scalcal_real)1e-6 * q.gain0;
    q.step[6 + k] = (scalcal_real)1e-6;
  }
  for (k = 0; k < SC_P; ++k) p[k] = 0;
  for (k = 0; k < 3; ++k) p[k] = o[k], p[3 + k] = k == 0 || P != 4 ? q.gain0 : 0;
  if (P == 4) p[3] = q.gain0; /* the host's reduce: cbrt of three equal gains */
  if ((status = fit_groups(&q, p, P, options, r)) != SCALCAL_OK) return status;
  if ((status = errors_of(&q, p, P, r, x)) != SCALCAL_OK) return status;
  if ((status = calibration_of(set, options, r, x, total, values, &out)) != SCALCAL_OK) return status;
  *cal = out;
  return SCALCAL_OK;
}
