/* Per-pose sums: what the fit needs of the samples of one still pose, accumulated sample by sample
 * in constant memory (count, mean, scatter matrix), and the caller-owned set of poses the fit reads.
 * Samples are taken relative to the set's origin (its first sample), and while a pose is summed its
 * mean is kept relative to its own first sample, so that a float build keeps the digits of raw
 * counts near 32768; a stored pose keeps its mean relative to the origin (40 bytes in float). */
#ifndef SCALCAL_POSE_H
#define SCALCAL_POSE_H

#include <stdint.h>

#include "scalcal/real.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A pose being summed. Filled by scalcal_pose_sum_add (sample by sample) or scalcal_pose_sum_merge
 * (a block of samples at once, Chan's pairwise update). */
typedef struct {
  uint32_t count;          /* samples */
  uint32_t first, last;    /* the stream indices of its first and last sample (for the caller) */
  scalcal_real ref[3];     /* its first sample, minus the set's origin */
  scalcal_real mean[3];    /* its mean, minus origin and ref */
  scalcal_real scatter[6]; /* sum (x - mean)(x - mean)^T: xx, yy, zz, xy, yz, zx (units squared) */
} scalcal_pose_sum;

/* A stored pose: what the fit reads. */
typedef struct {
  uint32_t count;
  scalcal_real mean[3];    /* its mean minus the set's origin */
  scalcal_real scatter[6]; /* as in scalcal_pose_sum */
} scalcal_pose;

/* The poses of one calibration, in storage the caller owns (no malloc): capacity is the maximum
 * number of poses, fixed by the caller (SCALCAL_MAX_POSES by default). */
typedef struct {
  scalcal_pose* poses;
  uint32_t capacity, count;
  scalcal_real origin[3]; /* the first sample the set saw; every pose is stored relative to it */
  int has_origin;
  /* Set by the still-pose detector (0 for poses summed otherwise): the windows it judged once it had
   * a noise floor, and those of them that moved (variance norm above 3 times the floor). The fit
   * refuses a set whose stream moved in more than 3/4 of its windows (SCALCAL_E_MOVING). */
  uint32_t windows_judged, windows_moving;
} scalcal_pose_set;

/* Empties `set` over `storage` (capacity poses). SCALCAL_E_ARGUMENT for a null pointer or capacity 0. */
scalcal_status scalcal_pose_set_init(scalcal_pose_set* set, scalcal_pose* storage, uint32_t capacity);

/* Empties one sum. */
void scalcal_pose_sum_clear(scalcal_pose_sum* sum);

/* Adds one finite sample (raw units) taken at stream index `index`; the first sample the set ever
 * sees becomes its origin. The caller checks finiteness (the detector does). */
void scalcal_pose_sum_add(scalcal_pose_set* set, scalcal_pose_sum* sum, const scalcal_real sample[3], uint32_t index);

/* into += from (both relative to the same set): the sum of their samples together. */
void scalcal_pose_sum_merge(scalcal_pose_sum* into, const scalcal_pose_sum* from);

/* The Euclidean norm over the three axes of the per-axis population variances (scatter / count):
 * the statistic the still-pose detector thresholds (units squared). */
scalcal_real scalcal_pose_sum_variance_norm(const scalcal_pose_sum* sum);

/* Stores `sum` as the set's next pose: SCALCAL_E_FULL when the set is full, SCALCAL_E_ARGUMENT when
 * it has no sample. */
scalcal_status scalcal_pose_set_append(scalcal_pose_set* set, const scalcal_pose_sum* sum);

/* The mean of pose i in raw units (origin + mean), and relative to the origin. */
void scalcal_pose_mean(const scalcal_pose_set* set, uint32_t i, scalcal_real mean[3]);
void scalcal_pose_mean_relative(const scalcal_pose_set* set, uint32_t i, scalcal_real mean[3]);

#ifdef __cplusplus
}
#endif

#endif
