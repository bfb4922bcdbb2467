/* The closed-form start in any units and the paper's convention of a correction (the host's
 * numeric/calibration/full_correction.cpp): an ellipsoid through the pose means by linear least
 * squares (Givens rotations row by row: no N x 9 matrix is stored), and the canonical form
 * physical = (diag(k) Phi)^-1 (raw - offset) with unit rows phi and phi_kj = phi_jk. */
#include <string.h>

#include "fit_internal.h"

/* Newton on the three off-diagonal phis: unit rows with phi_kj = phi_jk and the given cosines. */
static const int kPairs[3][2] = {{0, 1}, {1, 2}, {2, 0}};

static void axes_of(const scalcal_real q[3], scalcal_real P[9]) {
  int k, r;
  memset(P, 0, 9 * sizeof(scalcal_real));
  for (k = 0; k < 3; ++k) P[kPairs[k][0] * 3 + kPairs[k][1]] = P[kPairs[k][1] * 3 + kPairs[k][0]] = q[k];
  for (r = 0; r < 3; ++r) {
    scalcal_real s = 1, d;
    for (k = 0; k < 3; ++k)
      if (k != r) s -= P[r * 3 + k] * P[r * 3 + k];
    d = s > 0 ? SC_SQRT(s) : 0;
    P[r * 3 + r] = d;
  }
}

static void axes_residual(const scalcal_real q[3], const scalcal_real cosines[9], scalcal_real f[3]) {
  scalcal_real P[9];
  int k;
  axes_of(q, P);
  for (k = 0; k < 3; ++k) {
    const int a = kPairs[k][0], b = kPairs[k][1];
    f[k] = P[a * 3] * P[b * 3] + P[a * 3 + 1] * P[b * 3 + 1] + P[a * 3 + 2] * P[b * 3 + 2] - cosines[a * 3 + b];
  }
}

/* d f / d q analytically: row a . row b with P_rr = sqrt(1 - sum of row r's off-diagonals^2). */
static void axes_jacobian(const scalcal_real q[3], scalcal_real Jf[9]) {
  scalcal_real P[9], dP[9];
  int k, j, c;
  axes_of(q, P);
  for (j = 0; j < 3; ++j) {
    const int a = kPairs[j][0], b = kPairs[j][1];
    memset(dP, 0, sizeof dP);
    dP[a * 3 + b] = dP[b * 3 + a] = 1;
    if (P[a * 3 + a] > 0) dP[a * 3 + a] = -q[j] / P[a * 3 + a];
    if (P[b * 3 + b] > 0) dP[b * 3 + b] = -q[j] / P[b * 3 + b];
    for (k = 0; k < 3; ++k) {
      const int r = kPairs[k][0], s = kPairs[k][1];
      scalcal_real d = 0;
      for (c = 0; c < 3; ++c) d += dP[r * 3 + c] * P[s * 3 + c] + P[r * 3 + c] * dP[s * 3 + c];
      Jf[k * 3 + j] = d;
    }
  }
}

static scalcal_real max_abs3(const scalcal_real v[3]) {
  scalcal_real m = SC_FABS(v[0]);
  if (SC_FABS(v[1]) > m) m = SC_FABS(v[1]);
  if (SC_FABS(v[2]) > m) m = SC_FABS(v[2]);
  return m;
}

int sc_canonical(const scalcal_real matrix[9], const scalcal_real offset[3], sc_correction* out) {
  scalcal_real S[9], W[9], cosines[9], q[3], f[3], Jf[9], Jinv[9], P[9], KP[9];
  int i, j, it;
  if (sc_inverse3(matrix, S) == 0 || !sc_finite(S[0])) return 0;
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j)
      W[i * 3 + j] = S[i * 3] * S[j * 3] + S[i * 3 + 1] * S[j * 3 + 1] + S[i * 3 + 2] * S[j * 3 + 2];
  for (i = 0; i < 3; ++i) out->scale[i] = SC_SQRT(W[i * 3 + i]);
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) cosines[i * 3 + j] = W[i * 3 + j] / (out->scale[i] * out->scale[j]);
  for (i = 0; i < 3; ++i) q[i] = cosines[kPairs[i][0] * 3 + kPairs[i][1]] / 2;
  for (it = 0; it < 50; ++it) {
    scalcal_real d[3];
    axes_residual(q, cosines, f);
    if (!(max_abs3(f) >= SC_CANONICAL_STOP)) break;
    axes_jacobian(q, Jf);
    if (sc_inverse3(Jf, Jinv) == 0) return 0;
    sc_mul3v(Jinv, f, d);
    for (i = 0; i < 3; ++i) q[i] -= d[i];
  }
  axes_residual(q, cosines, f);
  if (!(max_abs3(f) < SC_CANONICAL_ACCEPT)) return 0;
  axes_of(q, P);
  for (i = 0; i < 3; ++i) out->nonorthogonality[i] = 2 * q[i];
  for (i = 0; i < 9; ++i) KP[i] = out->scale[i / 3] * P[i];
  if (sc_inverse3(KP, out->matrix) == 0) return 0;
  for (i = 0; i < 3; ++i) out->offset[i] = offset[i];
  return 1;
}

/* One row of the least squares x . a = 1, rotated into R (k x k upper) and z = Q^T 1. */
static void givens_add(int k, scalcal_real* R, scalcal_real* z, scalcal_real* x) {
  scalcal_real rhs = 1;
  int j, c;
  for (j = 0; j < k; ++j) {
    scalcal_real r, cs, sn, a = R[j * k + j], b = x[j];
    if (b == 0) continue;
    r = SC_SQRT(a * a + b * b);
    cs = a / r;
    sn = b / r;
    for (c = j; c < k; ++c) {
      const scalcal_real rc = R[j * k + c], xc = x[c];
      R[j * k + c] = cs * rc + sn * xc;
      x[c] = -sn * rc + cs * xc;
    }
    r = z[j];
    z[j] = cs * r + sn * rhs;
    rhs = -sn * r + cs * rhs;
  }
}

static void quadric_row(sc_shape shape, const scalcal_real v[3], scalcal_real* x) {
  if (shape == SC_SHAPE_GENERAL) {
    x[0] = v[0] * v[0], x[1] = v[1] * v[1], x[2] = v[2] * v[2];
    x[3] = 2 * v[0] * v[1], x[4] = 2 * v[1] * v[2], x[5] = 2 * v[0] * v[2];
    x[6] = v[0], x[7] = v[1], x[8] = v[2];
  } else if (shape == SC_SHAPE_AXIS_ALIGNED) {
    x[0] = v[0] * v[0], x[1] = v[1] * v[1], x[2] = v[2] * v[2];
    x[3] = v[0], x[4] = v[1], x[5] = v[2];
  } else {
    x[0] = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    x[1] = v[0], x[2] = v[1], x[3] = v[2];
  }
}

/* The quadric u^T A u + b^T u = 1 of one shape through the scaled means; 0 when rank-deficient. */
static int quadric(const sc_problem* q, sc_shape shape, const scalcal_real centre[3], scalcal_real spread,
                   scalcal_real A[9], scalcal_real b[3]) {
  const int k = shape == SC_SHAPE_GENERAL ? 9 : shape == SC_SHAPE_AXIS_ALIGNED ? 6 : 4;
  scalcal_real R[81], z[9], x[9], a[9], largest = 0;
  uint32_t i;
  int j, c;
  if (q->set->count < (uint32_t)k) return 0;
  memset(R, 0, sizeof R);
  memset(z, 0, sizeof z);
  for (i = 0; i < q->set->count; ++i) {
    scalcal_real m[3], u[3];
    scalcal_pose_mean_relative(q->set, i, m);
    for (j = 0; j < 3; ++j) u[j] = (m[j] - centre[j]) / spread;
    quadric_row(shape, u, x);
    givens_add(k, R, z, x);
  }
  for (j = 0; j < k; ++j)
    if (SC_FABS(R[j * k + j]) > largest) largest = SC_FABS(R[j * k + j]);
  for (j = k - 1; j >= 0; --j) {
    scalcal_real s = z[j];
    if (!(SC_FABS(R[j * k + j]) > (scalcal_real)k * SCALCAL_EPSILON * largest)) return 0;
    for (c = j + 1; c < k; ++c) s -= R[j * k + c] * a[c];
    a[j] = s / R[j * k + j];
  }
  memset(A, 0, 9 * sizeof(scalcal_real));
  if (shape == SC_SHAPE_GENERAL) {
    A[0] = a[0], A[4] = a[1], A[8] = a[2];
    A[1] = A[3] = a[3], A[5] = A[7] = a[4], A[2] = A[6] = a[5];
    b[0] = a[6], b[1] = a[7], b[2] = a[8];
  } else if (shape == SC_SHAPE_AXIS_ALIGNED) {
    A[0] = a[0], A[4] = a[1], A[8] = a[2];
    b[0] = a[3], b[1] = a[4], b[2] = a[5];
  } else {
    A[0] = A[4] = A[8] = a[0];
    b[0] = a[1], b[1] = a[2], b[2] = a[3];
  }
  return 1;
}

/* From the quadric to a correction: centre o, |L (u - o)| = 1 with L = (A / r)^(1/2) symmetric. */
static int quadric_correction(const scalcal_real A[9], const scalcal_real b[3], const scalcal_real centre[3],
                              scalcal_real spread, scalcal_real magnitude, sc_correction* out) {
  scalcal_real l[9], o[3], Ao[3], r, Ar[9], values[3], vectors[9], L[9], matrix[9], offset[3];
  int i, j;
  memcpy(l, A, sizeof l);
  if (!sc_cholesky(3, l)) return 0; /* not an ellipsoid */
  sc_cholesky_solve(3, l, b, o);
  for (i = 0; i < 3; ++i) o[i] *= (scalcal_real)-0.5;
  sc_mul3v(A, o, Ao);
  r = 1 + o[0] * Ao[0] + o[1] * Ao[1] + o[2] * Ao[2];
  if (!(r > 0)) return 0;
  for (i = 0; i < 9; ++i) Ar[i] = A[i] / r;
  sc_eigen_symmetric(3, Ar, values, vectors);
  for (i = 0; i < 3; ++i) {
    if (!(values[i] > 0)) return 0;
    values[i] = SC_SQRT(values[i]);
  }
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j)
      L[i * 3 + j] = vectors[i * 3] * values[0] * vectors[j * 3] + vectors[i * 3 + 1] * values[1] * vectors[j * 3 + 1] +
                     vectors[i * 3 + 2] * values[2] * vectors[j * 3 + 2];
  for (i = 0; i < 3; ++i) offset[i] = centre[i] + spread * o[i];
  for (i = 0; i < 9; ++i) matrix[i] = (magnitude / spread) * L[i];
  return sc_canonical(matrix, offset, out);
}

int sc_fit_ellipsoid(const sc_problem* q, scalcal_real magnitude, sc_shape shape, sc_correction* out) {
  const uint32_t n = q->set->count;
  scalcal_real centre[3] = {0, 0, 0}, spread = 0, A[9], b[3];
  uint32_t i;
  int j;
  if (n < 4) return 0;
  /* Centred and scaled: raw counts near 32768 would make the normal equations useless. */
  for (i = 0; i < n; ++i) {
    scalcal_real m[3];
    scalcal_pose_mean_relative(q->set, i, m);
    for (j = 0; j < 3; ++j) centre[j] += m[j];
  }
  for (j = 0; j < 3; ++j) centre[j] /= (scalcal_real)n;
  for (i = 0; i < n; ++i) {
    scalcal_real m[3];
    scalcal_pose_mean_relative(q->set, i, m);
    for (j = 0; j < 3; ++j) spread += (m[j] - centre[j]) * (m[j] - centre[j]);
  }
  spread = SC_SQRT(spread / (scalcal_real)n);
  if (!(spread > 0)) return 0;
  if (quadric(q, shape, centre, spread, A, b) && quadric_correction(A, b, centre, spread, magnitude, out)) return 1;
  /* The general ellipsoid falls back to the axis-aligned one, as the host's does. */
  if (shape == SC_SHAPE_GENERAL && quadric(q, SC_SHAPE_AXIS_ALIGNED, centre, spread, A, b) &&
      quadric_correction(A, b, centre, spread, magnitude, out))
    return 1;
  return 0;
}
