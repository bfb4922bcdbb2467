/* Noise, residuals and standard errors at the estimate (the host's calibrate_model and
 * calibrate_any_units): the covariance from the noise within poses (K per unit of a sample's
 * variance), from the residuals between poses (s^2 (H^T W H)^-1) and, where it applies, from the
 * between-pose error model (between_poses.c), each in the reported units. */
#include <string.h>

#include "fit_internal.h"

static scalcal_real larger(scalcal_real p, scalcal_real a) {
  if (p != p) return a;
  if (a != a) return p;
  return p > a ? p : a;
}

/* sqrt of the diagonal of a covariance of the estimator's parameters, in the reported units: the
 * bias through the start to raw units, the scale deviations relative to their geometric mean when
 * the start set the nominal gain. */
static void reported_std(const sc_problem* q, const scalcal_real* cov, scalcal_real* out) {
  const int p = q->p;
  const scalcal_real M = q->magnitude;
  scalcal_real Ti[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, C[9], TC[9];
  int i, j, k;
  for (k = 0; k < p; ++k) out[k] = cov[k * p + k] > 0 ? SC_SQRT(cov[k * p + k]) : 0;
  if (q->started) sc_inverse3(q->start.matrix, Ti);
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) C[i * 3 + j] = cov[i * p + j];
  sc_mul3(Ti, C, TC);
  for (i = 0; i < 3; ++i) {
    scalcal_real d = 0;
    for (k = 0; k < 3; ++k) d += TC[i * 3 + k] * Ti[i * 3 + k];
    d *= M * M;
    out[i] = d > 0 ? SC_SQRT(d) : 0;
  }
  if (p >= 6 && q->started)
    for (i = 0; i < 3; ++i) { /* (I - 1/3) C (I - 1/3)^T, diagonal */
      scalcal_real d = 0;
      for (j = 0; j < 3; ++j)
        for (k = 0; k < 3; ++k)
          d += ((i == j) - (scalcal_real)1 / 3) * cov[(3 + j) * p + 3 + k] * ((i == k) - (scalcal_real)1 / 3);
      out[3 + i] = d > 0 ? SC_SQRT(d) : 0;
    }
}

/* The gains' standard errors from one covariance (scaled by `factor`), and the nominal gain's. */
static void gain_std(const scalcal_calibration* cal, int p, const scalcal_real* cov, scalcal_real factor,
                     scalcal_real g[3], scalcal_real* nominal) {
  scalcal_real sum = 0;
  int i, j;
  /* gain_i = nominal gain (1 + dk_i): its relative error is dk_i's, the common part included, with
   * an unknown magnitude too (the host's gain_errors); only the scale deviations lose it. */
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) sum += factor * cov[(3 + i) * p + 3 + j];
  for (i = 0; i < 3; ++i) {
    const scalcal_real d = factor * cov[(3 + i) * p + 3 + i];
    g[i] = cal->gain[i] * (d > 0 ? SC_SQRT(d) : 0);
  }
  *nominal = cal->nominal_gain * (sum > 0 ? SC_SQRT(sum) : 0) / 3;
}

/* The information sum w h h^T at the estimate (weights 1/n_i when inverse_counts), K its inverse. */
static int information(const sc_problem* q, const sc_meter* m, int inverse_counts, scalcal_real* info) {
  const int p = q->p;
  scalcal_real c[3], h[SC_P];
  uint32_t i;
  int r, s;
  memset(info, 0, sizeof(scalcal_real) * (unsigned)(p * p));
  for (i = 0; i < q->set->count; ++i) {
    const scalcal_real norm = sc_compensate(q, m, i, c);
    const scalcal_real e[3] = {c[0] / norm, c[1] / norm, c[2] / norm};
    const scalcal_real w = inverse_counts ? 1 / (scalcal_real)q->set->poses[i].count : sc_problem_weight(q, i);
    sc_row(e, h);
    for (r = 0; r < p; ++r)
      for (s = 0; s < p; ++s) info[r * p + s] += w * h[r] * h[s];
  }
  return 1;
}

/* The noise (pooled scatter within poses, else the residuals) and the residuals' sums. */
static void noise_and_residuals(const sc_problem* q, const sc_meter* m, scalcal_calibration* cal,
                                scalcal_fit_report* report, scalcal_real* weighted) {
  const uint32_t n = q->set->count;
  const scalcal_real M = q->magnitude;
  scalcal_real c[3], ss = 0, scatter = 0;
  uint32_t i, samples = 0;
  *weighted = 0;
  for (i = 0; i < n; ++i) {
    const scalcal_real norm = sc_compensate(q, m, i, c);
    const scalcal_real J = sc_cell_modulus(q, m, i, c, norm) / M - 1;
    ss += J * J;
    *weighted += sc_problem_weight(q, i) * J * J;
    samples += q->set->poses[i].count;
    scatter += sc_radial_scatter(q, m, i, c, norm);
  }
  cal->residual_rms = SC_SQRT(ss / (scalcal_real)n) * M;
  report->noise_source = SCALCAL_NOISE_NONE;
  cal->noise = 0;
  if (q->tumbling) {
    /* The noise is the second differences'. A sample's residual is its cell's mean residual plus its
     * deviation from it, which the cell's radial scatter does not give (the arc's sagitta enters it
     * at the same order as the noise): the per-sample RMS is taken as the cells' weighted residuals
     * plus the noise within them. The residual-based errors below use the cells' residuals only
     * (between cells, weighted by their samples, dof cells - P): batch means over directions. */
    cal->noise = q->noise;
    cal->residual_rms = SC_SQRT((*weighted + (scalcal_real)(samples - n) * (q->noise / M) * (q->noise / M)) /
                                (scalcal_real)samples) * M;
    report->noise_source = q->noise > 0 ? SCALCAL_NOISE_DIFFERENCES : SCALCAL_NOISE_NONE;
    report->chi_square = (scalcal_real)NAN;
    return;
  }
  if (q->noise > 0) {
    cal->noise = q->noise;
    report->noise_source = SCALCAL_NOISE_GIVEN;
  } else if (samples > n) {
    cal->noise = SC_SQRT(scatter / (scalcal_real)(samples - n));
    report->noise_source = SCALCAL_NOISE_SCATTER;
  } else if (n > (uint32_t)q->p) {
    cal->noise = SC_SQRT(ss / (scalcal_real)(n - (uint32_t)q->p)) * M;
    report->noise_source = SCALCAL_NOISE_RESIDUALS;
  }
  report->chi_square = (scalcal_real)NAN;
  if (report->noise_source >= SCALCAL_NOISE_SCATTER && report->noise_source != SCALCAL_NOISE_RESIDUALS &&
      cal->noise > 0 && n > (uint32_t)q->p) {
    scalcal_real chi = 0;
    for (i = 0; i < n; ++i) {
      const scalcal_real z =
          (sc_compensate(q, m, i, c) / M - 1) * M * SC_SQRT((scalcal_real)q->set->poses[i].count) / cal->noise;
      chi += z * z;
    }
    report->chi_square = chi;
  }
}

/* The reported standard errors from one covariance (scaled by factor): se and the gains'. */
static void from_covariance(const sc_problem* q, const scalcal_calibration* cal, const scalcal_real* cov,
                            scalcal_real factor, scalcal_real* scratch, scalcal_real* se, scalcal_real g[3],
                            scalcal_real* nominal) {
  int k;
  for (k = 0; k < q->p * q->p; ++k) scratch[k] = factor * cov[k];
  reported_std(q, scratch, se);
  if (q->p >= 6) gain_std(cal, q->p, cov, factor, g, nominal);
}

/* The between-pose error model's standard errors into the report (A and B: P x P scratch). */
static int error_model(const sc_problem* q, const sc_meter* m, const scalcal_real* K, scalcal_calibration* cal,
                       scalcal_fit_report* report, scalcal_real* A, scalcal_real* B, scalcal_real g[3],
                       scalcal_real* nominal) {
  const scalcal_real M = q->magnitude;
  sc_between b;
  if (report->noise_source != SCALCAL_NOISE_SCATTER && report->noise_source != SCALCAL_NOISE_GIVEN) return 0;
  if (q->tumbling) return 0; /* cells are not poses: no scatter between them to model */
  if (report->dof < SC_ERROR_MODEL_DOF) return 0;
  if (!sc_between_poses(q, m, (cal->noise / M) * (cal->noise / M), K, A, B, &b)) return 0;
  report->error_model = 1;
  report->error_model_iterations = b.iterations;
  report->between_std = SC_SQRT(b.between) * M;
  report->within_std = cal->noise;
  from_covariance(q, cal, B, 1, A, report->model_std, g, nominal);
  return 1;
}

void sc_standard_errors(const sc_problem* q, const scalcal_real* X, scalcal_calibration* cal,
                        scalcal_fit_report* report) {
  const int p = q->p;
  const scalcal_real M = q->magnitude, nan = (scalcal_real)NAN;
  /* K: (H^T W H)^-1; Kn: the covariance per unit of a sample's variance; A, B: scratch. */
  scalcal_real K[SC_P * SC_P], A[SC_P * SC_P], B[SC_P * SC_P], se[SC_P], gp[3], ga[3], gm[3], np, na, nm, weighted,
      s2 = 0, v2;
  const scalcal_real* Kn = K;
  sc_meter m;
  int k, has_noise, has_residuals, modelled;
  sc_meter_of(q, X, &m);
  information(q, &m, 0, K);
  if (!sc_spd_inverse(p, K, K)) memset(K, 0, sizeof K);
  if (!q->weight_by_samples) { /* equal weights: the covariance is K (sum h h^T / n_i) K per sigma^2 */
    information(q, &m, 1, A);
    sc_mul(p, A, K, B);
    sc_mul(p, K, B, A);
    Kn = A;
  }
  noise_and_residuals(q, &m, cal, report, &weighted);
  report->dof = (int)q->set->count - p;
  has_noise = report->noise_source != SCALCAL_NOISE_NONE;
  has_residuals = report->dof > 0;
  if (has_residuals) s2 = weighted / (scalcal_real)report->dof;
  v2 = (cal->noise / M) * (cal->noise / M);
  gp[0] = gp[1] = gp[2] = np = ga[0] = ga[1] = ga[2] = na = nan;
  from_covariance(q, cal, Kn, v2, B, report->predicted_std, gp, &np);
  from_covariance(q, cal, K, s2, B, report->achieved_std, ga, &na);
  report->between_std = report->within_std = nan;
  for (k = 0; k < p; ++k) report->model_std[k] = nan;
  modelled = error_model(q, &m, K, cal, report, A, B, gm, &nm); /* A (Kn) is spent from here */
  for (k = 0; k < p; ++k) {
    if (!has_noise) report->predicted_std[k] = nan;
    if (!has_residuals) report->achieved_std[k] = nan;
    se[k] = modelled ? report->model_std[k] : larger(report->predicted_std[k], report->achieved_std[k]);
  }
  for (k = 0; k < 3; ++k) {
    cal->bias_std[k] = se[k];
    cal->scale_deviation_std[k] = p >= 6 ? se[3 + k] : nan;
    cal->nonorthogonality_std[k] = p >= 9 ? se[6 + k] : nan;
    cal->gain_std[k] = nan;
  }
  cal->nominal_gain_std = nan;
  if (p >= 6) {
    if (!has_noise) gp[0] = gp[1] = gp[2] = np = nan;
    if (!has_residuals) ga[0] = ga[1] = ga[2] = na = nan;
    for (k = 0; k < 3; ++k) cal->gain_std[k] = modelled ? gm[k] : larger(gp[k], ga[k]);
    cal->nominal_gain_std = modelled ? nm : larger(np, na);
  }
}
