/* What a pose's scatter matrix says of its samples' moduli (fit_internal.h): their first-order
 * scatter (the noise within still poses), and for a tumbling cell, whose samples spread over an arc
 * of the sphere, the mean of their moduli to second order (the fit's per-sample residuals, summed). */
#include <string.h>

#include "fit_internal.h"

static const int kPair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};

/* A = G^-1 T: a raw deviation's image in c. */
static void raw_to_c(const sc_problem* q, const sc_meter* m, scalcal_real A[9]) {
  if (q->started)
    sc_mul3(m->Ginv, q->start.matrix, A);
  else
    memcpy(A, m->Ginv, sizeof(scalcal_real) * 9);
}

/* w^T S w for the packed scatter S (xx, yy, zz, xy, yz, zx). */
static scalcal_real quadratic(const scalcal_real S[6], const scalcal_real w[3]) {
  scalcal_real s = 0;
  int k;
  for (k = 0; k < 6; ++k) s += (k < 3 ? 1 : 2) * S[k] * w[kPair[k][0]] * w[kPair[k][1]];
  return s;
}

scalcal_real sc_radial_scatter(const sc_problem* q, const sc_meter* m, uint32_t i, const scalcal_real c[3],
                               scalcal_real norm) {
  scalcal_real A[9], w[3];
  int k;
  raw_to_c(q, m, A);
  for (k = 0; k < 3; ++k) w[k] = (c[0] * A[k] + c[1] * A[3 + k] + c[2] * A[6 + k]) / norm; /* A^T u */
  return quadratic(q->set->poses[i].scatter, w);
}

scalcal_real sc_cell_modulus(const sc_problem* q, const sc_meter* m, uint32_t i, const scalcal_real c[3],
                             scalcal_real norm) {
  scalcal_real A[9], w[3], mean_square, noise = 0;
  int r;
  if (!q->tumbling) return norm;
  /* The squared modulus is a quadratic form of the sample: its mean over the cell is exact from the
   * sums, |c|^2 + tr(A S A^T) / n, however far the cell spreads over the sphere. The mean of the
   * moduli is its square root less var(|c_i|^2) / (8 mean^(3/2)); on the fitted sphere |c_i|^2
   * varies only with the radial noise, var = 4 mean s^2 (s^2 = u^T A N A^T u, N the per-axis noise
   * variances in raw units), so the mean modulus is sqrt(mean) - s^2 / (2 sqrt(mean)) (times
   * (n - 1) / n, below). What is
   * left: terms of fourth order in the noise, and the misfit's variation within the cell (an
   * expansion of |c_i| about the cell's mean instead would leave the fourth order of the cell's
   * angular spread: 1.6 standard errors on the rehearsal with 64 cells). */
  raw_to_c(q, m, A);
  mean_square = norm * norm;
  for (r = 0; r < 3; ++r) {
    w[0] = A[3 * r], w[1] = A[3 * r + 1], w[2] = A[3 * r + 2];
    mean_square += quadratic(q->set->poses[i].scatter, w) / (scalcal_real)q->set->poses[i].count;
  }
  for (r = 0; r < 3; ++r) { /* (A^T u)_r^2 N_r */
    const scalcal_real v = (c[0] * A[r] + c[1] * A[3 + r] + c[2] * A[6 + r]) / norm;
    noise += v * v * q->raw_noise[r] * q->raw_noise[r];
  }
  /* The cell's own scatter of |c_i|^2 about its mean has (n - 1) / n of the variance: 0 for one sample. */
  noise *= (scalcal_real)(q->set->poses[i].count - 1) / (scalcal_real)q->set->poses[i].count;
  mean_square = SC_SQRT(mean_square);
  return mean_square - noise / (2 * mean_square);
}

scalcal_real sc_tumbling_noise(const sc_problem* q, const sc_meter* m) {
  scalcal_real A[9], s = 0;
  int k;
  raw_to_c(q, m, A);
  for (k = 0; k < 9; ++k) s += A[k] * A[k] * q->raw_noise[k % 3] * q->raw_noise[k % 3];
  return SC_SQRT(s / 3);
}

