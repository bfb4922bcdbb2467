/* The fit's internal pieces (not installed): the problem (pose means as the estimator sees them,
 * through the start), the meter of an estimate, the ellipsoid start and the canonical correction,
 * the layout's condition, the estimator and the standard errors. */
#ifndef SCALCAL_FIT_INTERNAL_H
#define SCALCAL_FIT_INTERNAL_H

#include "internal.h"
#include "scalcal/fit.h"

/* Convergence of the estimator: a step below SC_TOLERANCE has converged; a step that no longer
 * lowers the residual has converged when below SC_TOLERANCE_FLOOR (the precision's floor). Double:
 * the host's 1e4 eps and its square root; float: what single precision resolves. */
#if defined(SCALCAL_LONG_DOUBLE) /* the host tests' reference: the double rules at its precision */
#define SC_TOLERANCE ((scalcal_real)1e4 * LDBL_EPSILON)
#define SC_TOLERANCE_FLOOR ((scalcal_real)3.3e-8) /* sqrt(1e4 eps) */
#define SC_CANONICAL_STOP ((scalcal_real)1e-18)
#define SC_CANONICAL_ACCEPT ((scalcal_real)1e-15)
#define SC_PAPER_STEP_MIN ((scalcal_real)0)
#define SC_STEP_IN_STANDARD_ERRORS ((scalcal_real)0)
#elif defined(SCALCAL_DOUBLE)
#define SC_TOLERANCE ((scalcal_real)1e4 * DBL_EPSILON)
#define SC_TOLERANCE_FLOOR ((scalcal_real)1.4901161193847656e-06) /* sqrt(1e4 eps) */
#define SC_CANONICAL_STOP ((scalcal_real)1e-15)
#define SC_CANONICAL_ACCEPT ((scalcal_real)1e-12)
#define SC_PAPER_STEP_MIN ((scalcal_real)0)
#define SC_STEP_IN_STANDARD_ERRORS ((scalcal_real)0)
#else
#define SC_TOLERANCE ((scalcal_real)8 * FLT_EPSILON)
#define SC_TOLERANCE_FLOOR ((scalcal_real)64 * FLT_EPSILON)
#define SC_CANONICAL_STOP ((scalcal_real)4 * FLT_EPSILON)
#define SC_CANONICAL_ACCEPT ((scalcal_real)1e-4)
/* In float the residual's rounding (J = |c| / |I| - 1 to a few eps) lets a tiny fraction of a step
 * that does not descend pass the line search: a step accepted only below this fraction counts as
 * not accepted (the paper's step has done what it can: Gauss-Newton with the exact derivative takes
 * over; Gauss-Newton's is at the rounding floor). */
#define SC_PAPER_STEP_MIN ((scalcal_real)0.0625)
/* The same rounding bounds what float resolves of the minimum: about eps / (the residuals' RMS) of a
 * standard error. A full step below this fraction of every parameter's (residual-based) standard
 * error has converged. */
#define SC_STEP_IN_STANDARD_ERRORS ((scalcal_real)1e-3)
#endif

/* Thresholds of the host (numeric/calibration/model_choice.hpp, identifiability.hpp, any_units.cpp,
 * model_calibration.cpp, commands/calibration/correct.cpp). */
#define SC_CARRY_CONDITION ((scalcal_real)1e4) /* a layout carries a model up to this condition */
#define SC_ILL_CONDITIONED ((scalcal_real)1e10)
#define SC_IN_UNITS ((scalcal_real)0.1)         /* data within 10 % of |I| need no start */
#define SC_MODEL_EDGE ((scalcal_real)0.5)       /* no parameter of the estimate beyond this */
#define SC_MATRIX_CONDITION ((scalcal_real)100) /* `scalcal correct` refuses a matrix beyond this */

typedef enum { SC_SHAPE_GENERAL, SC_SHAPE_AXIS_ALIGNED, SC_SHAPE_SPHERE } sc_shape;

/* A correction physical = matrix (raw - offset) and its paper form (canonical: phi_kj = phi_jk). */
typedef struct {
  scalcal_real offset[3];
  scalcal_real matrix[9];
  scalcal_real scale[3];
  scalcal_real nonorthogonality[3];
} sc_correction;

/* The pose means as the estimator sees them: y = T (m - o) when started, m (raw) otherwise; means are
 * taken relative to the set's origin when started (the start is translation-equivariant). */
typedef struct {
  const scalcal_pose_set* set;
  int p;
  scalcal_real magnitude;
  int weight_by_samples;
  int started;
  sc_correction start; /* its offset relative to the set's origin */
  scalcal_real noise;  /* one sample's noise given by the caller; 0: from the scatter within poses */
  /* Tumbling mode (scalcal/tumble.h): the poses are cells of moving samples; their per-axis noise in
   * raw units (second differences). */
  int tumbling;
  scalcal_real raw_noise[3];
} sc_problem;

void sc_problem_mean(const sc_problem* q, uint32_t i, scalcal_real y[3]);
scalcal_real sc_problem_weight(const sc_problem* q, uint32_t i);
/* The median over poses of |mean| / magnitude (the host's: element n/2 of the sorted ratios). */
scalcal_real sc_median_ratio(const sc_problem* q);

/* The meter of an estimate X (P entries): bias = X_b |I|, gains 1 + dk, Phi with phi_kj = phi_jk =
 * gamma / 2; G = diag(1 + dk) Phi and its inverse. */
typedef struct {
  scalcal_real bias[3], gain[3], phi[9], G[9], Ginv[9];
  int valid;
} sc_meter;
void sc_meter_of(const sc_problem* q, const scalcal_real* X, sc_meter* m);
/* c = G^-1 (y - bias) of pose i; returns |c|. */
scalcal_real sc_compensate(const sc_problem* q, const sc_meter* m, uint32_t i, scalcal_real c[3]);

/* The modulus the estimator fits for pose i, given c and |c| of sc_compensate: |c| for a still pose;
 * for a tumbling cell the mean of its samples' moduli, sqrt(q) - s^2 / (2 sqrt(q)) with q = |c|^2 +
 * tr(A S A^T) / n their mean square (A = G^-1 T the map of a raw deviation into c, S the cell's
 * scatter) and s^2 one sample's radial noise variance (cell_modulus.c derives it). */
scalcal_real sc_cell_modulus(const sc_problem* q, const sc_meter* m, uint32_t i, const scalcal_real c[3],
                             scalcal_real norm);
/* sum over pose i's samples of (u . A d)^2: the first-order scatter of their moduli (S as above). */
scalcal_real sc_radial_scatter(const sc_problem* q, const sc_meter* m, uint32_t i, const scalcal_real c[3],
                               scalcal_real norm);
/* Tumbling: one sample's noise in c's units at meter m, sqrt(tr(A diag(raw_noise^2) A^T) / 3), the
 * host's noise_relative times |I| (the radial part, averaged over directions). */
scalcal_real sc_tumbling_noise(const sc_problem* q, const sc_meter* m);

/* The closed-form start through the pose means (relative to the origin), |physical| = magnitude:
 * 1 on success. */
int sc_fit_ellipsoid(const sc_problem* q, scalcal_real magnitude, sc_shape shape, sc_correction* out);
/* matrix brought to the paper's convention: 1 on success, 0 when degenerate. */
int sc_canonical(const scalcal_real matrix[9], const scalcal_real offset[3], sc_correction* out);

/* Eigenvalues of H^T H (unit weights) of a P-parameter model at the given directions' source:
 * the directions of the pose means through `through` (NULL: the means themselves). Returns the
 * condition number (infinity when not of full rank in this precision). */
scalcal_real sc_layout_condition(const sc_problem* q, int p, const sc_correction* through);

/* The same at the fitted directions (the compensated means at X), under the problem's model. */
scalcal_real sc_fitted_condition(const sc_problem* q, const scalcal_real* X);

/* The estimator from X = 0 (numeric/calibration/model_calibration.cpp, damped_gauss_newton). */
void sc_estimate(const sc_problem* q, int max_iterations, scalcal_real* X, scalcal_fit_report* report);

/* The between-pose error model (between_poses.c): applies when the noise comes from the scatter
 * within poses and the poses outnumber the parameters by at least this (the host's kErrorModelDof). */
#define SC_ERROR_MODEL_DOF 5
typedef struct {
  scalcal_real between; /* sigma_b^2 by REML, >= 0 (the estimator's units: relative to |I|) */
  int iterations, converged;
} sc_between;
/* sigma_b^2 at the estimate (meter m) with one sample's variance `within` (relative to |I|^2), and
 * the estimator's covariance under the model, K B K, given K = (H^T W0 H)^-1: left in x. a and x are
 * P x P scratch. 0 when a weighted information matrix is not positive definite. */
int sc_between_poses(const sc_problem* q, const sc_meter* m, scalcal_real within, const scalcal_real* K,
                     scalcal_real* a, scalcal_real* x, sc_between* out);

/* Standard errors, noise and residuals at the estimate: fills cal's errors, noise, residual_rms and
 * the report's predicted/achieved standard errors and chi-square. */
void sc_standard_errors(const sc_problem* q, const scalcal_real* X, scalcal_calibration* cal,
                        scalcal_fit_report* report);

#endif
