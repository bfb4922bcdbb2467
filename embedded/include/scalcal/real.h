/* The precision, the sizes and the status codes every scalcal embedded header shares.
 * Precision is chosen at compile time: float by default, double with -DSCALCAL_DOUBLE (and, for the
 * host tests' reference only, long double with -DSCALCAL_LONG_DOUBLE: it needs libm's frexpl). */
#ifndef SCALCAL_REAL_H
#define SCALCAL_REAL_H

#include <float.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(SCALCAL_LONG_DOUBLE)
typedef long double scalcal_real;
#define SCALCAL_EPSILON LDBL_EPSILON
#elif defined(SCALCAL_DOUBLE)
typedef double scalcal_real;
#define SCALCAL_EPSILON DBL_EPSILON
#else
typedef float scalcal_real;
#define SCALCAL_EPSILON FLT_EPSILON
#endif

/* The default capacity of a pose set (scalcal_pose_set_init takes any capacity the caller stores). */
#ifndef SCALCAL_MAX_POSES
#define SCALCAL_MAX_POSES 64
#endif

/* The largest model: paper9's nine parameters (bias, scale-factor deviation, non-orthogonality). */
#define SCALCAL_MAX_PARAMETERS 9

/* The version of this library and of its flash record layout (scalcal/record.h). */
#define SCALCAL_EMBEDDED_VERSION 1

/* Every outcome a function of the library can report. Zero is success; the others say why nothing
 * usable was produced. scalcal_status_text() gives one line for each. */
typedef enum {
  SCALCAL_OK = 0,
  SCALCAL_E_ARGUMENT,         /* a null pointer, a capacity of 0, an option out of its range */
  SCALCAL_E_TOO_FEW_POSES,    /* fewer poses than the model has parameters (bias3 3, axis6 6, paper9 9) */
  SCALCAL_E_NOT_IDENTIFIABLE, /* the poses' directions cannot carry the model (rank or condition > 1e4) */
  SCALCAL_E_NO_START,         /* no ellipsoid passes near the pose means (too few or too flat for any units) */
  SCALCAL_E_MAGNITUDE,        /* the started poses' modulus is not within 0.5..2 of the magnitude */
  SCALCAL_E_NOT_CONVERGED,    /* the iteration stopped without converging: not to be used */
  SCALCAL_E_NOT_FINITE,       /* an input or a result that is NaN or infinite */
  SCALCAL_E_DEGENERATE,       /* the correction is singular, two axes nearly parallel, or its condition > 100 */
  SCALCAL_E_FULL,             /* the pose set is full: a still pose was not stored */
  SCALCAL_E_RECORD,           /* a flash record with a wrong magic, version, size or checksum */
  SCALCAL_E_MOVING,           /* the detector's stream moved most of the time: its "poses" are slow motion */
  SCALCAL_E_NO_RESTS          /* a rate table's log without two rests: its bias is not observed */
} scalcal_status;

/* One line describing a status (a string literal). */
const char* scalcal_status_text(scalcal_status status);

#ifdef __cplusplus
}
#endif

#endif
