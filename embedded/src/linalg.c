/* The small dense linear algebra of the fit (internal.h): Cholesky, symmetric Jacobi eigenvalues,
 * 3 x 3 inverse and products, and a root without libm. */
#include <stdint.h>
#include <string.h>

#include "internal.h"

int sc_finite(scalcal_real x) { return isfinite(x); }

#if defined(SCALCAL_LONG_DOUBLE) /* the host tests' reference: libm's */
scalcal_real sc_frexp(scalcal_real x, int* e) { return frexpl(x, e); }
scalcal_real sc_ldexp(scalcal_real x, int e) { return ldexpl(x, e); }
#else
#ifdef SCALCAL_DOUBLE
typedef uint64_t sc_bits;
#define SC_MANTISSA 52
#define SC_BIAS 1022
#define SC_EXPONENT_MASK 0x7FFu
#else
typedef uint32_t sc_bits;
#define SC_MANTISSA 23
#define SC_BIAS 126
#define SC_EXPONENT_MASK 0xFFu
#endif

scalcal_real sc_frexp(scalcal_real x, int* e) {
  sc_bits u;
  int shift = 0;
  if (!(x > 0) || !sc_finite(x)) return *e = 0, x;
  if (x < (scalcal_real)1 / ((sc_bits)1 << 30) / ((sc_bits)1 << 30)) x *= (scalcal_real)((sc_bits)1 << 30), shift = 30;
  memcpy(&u, &x, sizeof u);
  *e = (int)((u >> SC_MANTISSA) & SC_EXPONENT_MASK) - SC_BIAS - shift;
  u = (u & ~((sc_bits)SC_EXPONENT_MASK << SC_MANTISSA)) | ((sc_bits)SC_BIAS << SC_MANTISSA);
  memcpy(&x, &u, sizeof u);
  return x;
}

scalcal_real sc_ldexp(scalcal_real x, int e) {
  while (e != 0) {
    const int step = e > 60 ? 60 : e < -60 ? -60 : e;
    const sc_bits u = (sc_bits)(step + SC_BIAS + 1) << SC_MANTISSA; /* 2^step */
    scalcal_real p;
    memcpy(&p, &u, sizeof p);
    x *= p;
    e -= step;
  }
  return x;
}
#endif

scalcal_real sc_root(scalcal_real x, int p) {
  scalcal_real y, prev = 0;
  int e, i, k;
  if (!(x > 0) || !sc_finite(x)) return x > 0 ? x : 0;
  /* Start within a factor 2 of the root: 2^(e/p). */
  (void)sc_frexp(x, &e);
  y = sc_ldexp((scalcal_real)1, e / p);
  for (i = 0; i < 100; ++i) {
    scalcal_real power = 1;
    for (k = 0; k < p - 1; ++k) power *= y;
    prev = y;
    y = ((scalcal_real)(p - 1) * y + x / power) / (scalcal_real)p;
    if (y == prev) break;
  }
  return y;
}

void sc_row(const scalcal_real e[3], scalcal_real h[SC_P]) {
  h[0] = e[0];
  h[1] = e[1];
  h[2] = e[2];
  h[3] = e[0] * e[0];
  h[4] = e[1] * e[1];
  h[5] = e[2] * e[2];
  h[6] = e[0] * e[1];
  h[7] = e[1] * e[2];
  h[8] = e[2] * e[0];
}

int sc_cholesky(int p, scalcal_real* a) {
  int i, j, k;
  for (j = 0; j < p; ++j) {
    scalcal_real d = a[j * p + j];
    for (k = 0; k < j; ++k) d -= a[j * p + k] * a[j * p + k];
    if (!(d > 0)) return 0;
    d = SC_SQRT(d);
    a[j * p + j] = d;
    for (i = j + 1; i < p; ++i) {
      scalcal_real s = a[i * p + j];
      for (k = 0; k < j; ++k) s -= a[i * p + k] * a[j * p + k];
      a[i * p + j] = s / d;
    }
  }
  return 1;
}

void sc_cholesky_solve(int p, const scalcal_real* l, const scalcal_real* b, scalcal_real* x) {
  int i, k;
  for (i = 0; i < p; ++i) {
    scalcal_real s = b[i];
    for (k = 0; k < i; ++k) s -= l[i * p + k] * x[k];
    x[i] = s / l[i * p + i];
  }
  for (i = p - 1; i >= 0; --i) {
    scalcal_real s = x[i];
    for (k = i + 1; k < p; ++k) s -= l[k * p + i] * x[k];
    x[i] = s / l[i * p + i];
  }
}

int sc_spd_inverse(int p, const scalcal_real* a, scalcal_real* inv) {
  scalcal_real d[SC_P];
  int i, j, k;
  if (inv != a) memcpy(inv, a, sizeof(scalcal_real) * (unsigned)(p * p));
  if (!sc_cholesky(p, inv)) return 0;
  /* L^-1 in place, row by row, ascending within a row (LAPACK's trtri, unblocked). */
  for (i = 0; i < p; ++i) {
    for (j = 0; j < i; ++j) {
      scalcal_real s = 0;
      for (k = j; k < i; ++k) s += inv[i * p + k] * (k == j ? 1 / inv[j * p + j] : inv[k * p + j]);
      inv[i * p + j] = -s / inv[i * p + i];
    }
  }
  for (i = 0; i < p; ++i) inv[i * p + i] = 1 / inv[i * p + i];
  /* a^-1 = L^-T L^-1: the strict upper triangle, then the diagonal, then the mirror (in place). */
  for (i = 0; i < p; ++i)
    for (j = i + 1; j < p; ++j) {
      scalcal_real s = 0;
      for (k = j; k < p; ++k) s += inv[k * p + i] * inv[k * p + j];
      inv[i * p + j] = s;
    }
  for (i = 0; i < p; ++i) {
    d[i] = 0;
    for (k = i; k < p; ++k) d[i] += inv[k * p + i] * inv[k * p + i];
  }
  for (i = 0; i < p; ++i) {
    inv[i * p + i] = d[i];
    for (j = i + 1; j < p; ++j) inv[j * p + i] = inv[i * p + j];
  }
  return 1;
}

void sc_eigen_symmetric(int p, const scalcal_real* a, scalcal_real* values, scalcal_real* v) {
  scalcal_real m[SC_P * SC_P];
  int i, j, k, sweep;
  memcpy(m, a, sizeof(scalcal_real) * (unsigned)(p * p));
  if (v) {
    for (i = 0; i < p * p; ++i) v[i] = 0;
    for (i = 0; i < p; ++i) v[i * p + i] = 1;
  }
  for (sweep = 0; sweep < 60; ++sweep) {
    scalcal_real off = 0, diag = 0;
    for (i = 0; i < p; ++i) {
      diag += m[i * p + i] * m[i * p + i];
      for (j = i + 1; j < p; ++j) off += m[i * p + j] * m[i * p + j];
    }
    if (!(off > SCALCAL_EPSILON * SCALCAL_EPSILON * diag * (scalcal_real)1e-4)) break;
    for (i = 0; i < p; ++i)
      for (j = i + 1; j < p; ++j) {
        scalcal_real apq = m[i * p + j], theta, t, c, s;
        if (apq == 0) continue;
        theta = (m[j * p + j] - m[i * p + i]) / (2 * apq);
        t = (theta >= 0 ? 1 : -1) / (SC_FABS(theta) + SC_SQRT(theta * theta + 1));
        c = 1 / SC_SQRT(t * t + 1);
        s = t * c;
        for (k = 0; k < p; ++k) { /* columns i, j */
          scalcal_real mki = m[k * p + i], mkj = m[k * p + j];
          m[k * p + i] = c * mki - s * mkj;
          m[k * p + j] = s * mki + c * mkj;
        }
        for (k = 0; k < p; ++k) { /* rows i, j */
          scalcal_real mik = m[i * p + k], mjk = m[j * p + k];
          m[i * p + k] = c * mik - s * mjk;
          m[j * p + k] = s * mik + c * mjk;
        }
        for (k = 0; v && k < p; ++k) {
          scalcal_real vki = v[k * p + i], vkj = v[k * p + j];
          v[k * p + i] = c * vki - s * vkj;
          v[k * p + j] = s * vki + c * vkj;
        }
      }
  }
  /* Ascending, with their vectors (selection sort: p <= 9). */
  for (i = 0; i < p; ++i) values[i] = m[i * p + i];
  for (i = 0; i < p; ++i) {
    int best = i;
    for (j = i + 1; j < p; ++j)
      if (values[j] < values[best]) best = j;
    if (best != i) {
      scalcal_real t = values[i];
      values[i] = values[best];
      values[best] = t;
      for (k = 0; v && k < p; ++k) {
        t = v[k * p + i];
        v[k * p + i] = v[k * p + best];
        v[k * p + best] = t;
      }
    }
  }
}

scalcal_real sc_inverse3(const scalcal_real a[9], scalcal_real inv[9]) {
  scalcal_real c[9], det;
  int i;
  c[0] = a[4] * a[8] - a[5] * a[7];
  c[1] = a[2] * a[7] - a[1] * a[8];
  c[2] = a[1] * a[5] - a[2] * a[4];
  c[3] = a[5] * a[6] - a[3] * a[8];
  c[4] = a[0] * a[8] - a[2] * a[6];
  c[5] = a[2] * a[3] - a[0] * a[5];
  c[6] = a[3] * a[7] - a[4] * a[6];
  c[7] = a[1] * a[6] - a[0] * a[7];
  c[8] = a[0] * a[4] - a[1] * a[3];
  det = a[0] * c[0] + a[1] * c[3] + a[2] * c[6];
  if (det == 0 || !sc_finite(det)) return det;
  for (i = 0; i < 9; ++i) inv[i] = c[i] / det;
  return det;
}

void sc_mul3(const scalcal_real a[9], const scalcal_real b[9], scalcal_real out[9]) {
  scalcal_real r[9];
  int i, j;
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) r[i * 3 + j] = a[i * 3] * b[j] + a[i * 3 + 1] * b[3 + j] + a[i * 3 + 2] * b[6 + j];
  memcpy(out, r, sizeof r);
}

void sc_mul3v(const scalcal_real a[9], const scalcal_real v[3], scalcal_real out[3]) {
  scalcal_real r[3];
  int i;
  for (i = 0; i < 3; ++i) r[i] = a[i * 3] * v[0] + a[i * 3 + 1] * v[1] + a[i * 3 + 2] * v[2];
  memcpy(out, r, sizeof r);
}

scalcal_real sc_norm3(const scalcal_real v[3]) { return SC_SQRT(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

void sc_mul(int p, const scalcal_real* a, const scalcal_real* b, scalcal_real* out) {
  int i, j, k;
  for (i = 0; i < p; ++i)
    for (j = 0; j < p; ++j) {
      scalcal_real s = 0;
      for (k = 0; k < p; ++k) s += a[i * p + k] * b[k * p + j];
      out[i * p + j] = s;
    }
}
