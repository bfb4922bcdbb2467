/* What the library's sources share and its users never see: the math functions of the chosen
 * precision, the small dense linear algebra of the fit (at most 9 x 9, row-major, on the stack),
 * and the model's design row. No state: every function works on what it is given. */
#ifndef SCALCAL_INTERNAL_H
#define SCALCAL_INTERNAL_H

#include <math.h>

#include "scalcal/real.h"

#if defined(SCALCAL_LONG_DOUBLE)
#define SC_SQRT(x) sqrtl(x)
#define SC_FABS(x) fabsl(x)
#elif defined(SCALCAL_DOUBLE)
#define SC_SQRT(x) sqrt(x)
#define SC_FABS(x) fabs(x)
#else
#define SC_SQRT(x) sqrtf(x)
#define SC_FABS(x) fabsf(x)
#endif

#define SC_P SCALCAL_MAX_PARAMETERS

/* Finite: neither NaN nor infinite. */
int sc_finite(scalcal_real x);

/* frexp and ldexp on the bits of an IEEE value (no libm: newlib's set errno, which pulls a 1 KB
 * reentrancy structure into RAM). sc_frexp: x = f 2^e with f in [0.5, 1), for finite x > 0.
 * sc_ldexp: x 2^e, exact while the result is a normal number. */
scalcal_real sc_frexp(scalcal_real x, int* e);
scalcal_real sc_ldexp(scalcal_real x, int e);

/* x^(1/p) for x > 0 by Newton's method from a frexp start: the same bits on every target (no libm
 * pow or cbrt, whose last bits differ between C libraries). */
scalcal_real sc_root(scalcal_real x, int p);

/* The paper's design row h(eta) = (x, y, z, x^2, y^2, z^2, xy, yz, zx); a model of P parameters
 * (bias3, axis6, paper9) uses its first P entries. */
void sc_row(const scalcal_real eta[3], scalcal_real h[SC_P]);

/* a (P x P, symmetric) = L L^T in place (lower triangle); 0 when a pivot is not positive. */
int sc_cholesky(int p, scalcal_real* a);
/* Solves L L^T x = b with the factor of sc_cholesky (b may be x). */
void sc_cholesky_solve(int p, const scalcal_real* l, const scalcal_real* b, scalcal_real* x);
/* inverse = a^-1 for a symmetric positive definite a (inverse may be a); 0 when it is not. */
int sc_spd_inverse(int p, const scalcal_real* a, scalcal_real* inverse);

/* The eigenvalues (ascending) and, when vectors is not null, the eigenvectors (columns, row-major
 * P x P, accumulated in place) of a symmetric P x P matrix, by cyclic Jacobi rotations. */
void sc_eigen_symmetric(int p, const scalcal_real* a, scalcal_real* values, scalcal_real* vectors);

/* 3 x 3: the inverse by cofactors (returns the determinant; inverse untouched when it is 0),
 * products. */
scalcal_real sc_inverse3(const scalcal_real a[9], scalcal_real inverse[9]);
void sc_mul3(const scalcal_real a[9], const scalcal_real b[9], scalcal_real out[9]);
void sc_mul3v(const scalcal_real a[9], const scalcal_real v[3], scalcal_real out[3]);
scalcal_real sc_norm3(const scalcal_real v[3]);

/* P x P products for the covariances: out = a b (out must not be a or b). */
void sc_mul(int p, const scalcal_real* a, const scalcal_real* b, scalcal_real* out);

#endif
