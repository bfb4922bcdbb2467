/* Per-pose sums: what the fit needs of the samples of one still pose, accumulated sample by sample
 * in constant memory (count, mean, scatter matrix), and the caller-owned set of poses the fit reads.
 * Samples are stored relative to the set's origin (its first sample) and each pose's mean relative
 * to its own first sample, so that a float build keeps the digits of raw counts near 32768. */
#ifndef SCALCAL_POSE_H
#define SCALCAL_POSE_H

#include <stdint.h>

#include "scalcal/real.h"

/* One still pose. Filled by scalcal_pose_add (sample by sample) or scalcal_pose_merge (a block of
 * samples at once, Chan's pairwise update); read by the fit through scalcal_pose_mean. */
typedef struct {
  uint32_t count;          /* samples */
  uint32_t first, last;    /* the stream indices of its first and last sample (for the caller) */
  scalcal_real ref[3];     /* its first sample, minus the set's origin */
  scalcal_real mean[3];    /* its mean, minus origin and ref */
  scalcal_real scatter[6]; /* sum (x - mean)(x - mean)^T: xx, yy, zz, xy, yz, zx (units squared) */
} scalcal_pose;

/* The poses of one calibration, in storage the caller owns (no malloc): capacity is the maximum
 * number of poses, fixed by the caller (SCALCAL_MAX_POSES by default). */
typedef struct {
  scalcal_pose* poses;
  uint32_t capacity, count;
  scalcal_real origin[3]; /* the first sample the set saw; every pose is stored relative to it */
  int has_origin;
} scalcal_pose_set;

/* Empties `set` over `storage` (capacity poses). SCALCAL_E_ARGUMENT for a null pointer or capacity 0. */
scalcal_status scalcal_pose_set_init(scalcal_pose_set* set, scalcal_pose* storage, uint32_t capacity);

/* Empties one pose. */
void scalcal_pose_clear(scalcal_pose* pose);

/* Adds one finite sample (raw units) taken at stream index `index` to `pose`; the first sample the set
 * ever sees becomes its origin. The caller checks finiteness (the detector does). */
void scalcal_pose_add(scalcal_pose_set* set, scalcal_pose* pose, const scalcal_real sample[3], uint32_t index);

/* into += from (both relative to the same set): the pose of their samples together. */
void scalcal_pose_merge(scalcal_pose* into, const scalcal_pose* from);

/* Stores a copy of `pose` as the set's next pose: SCALCAL_E_FULL when the set is full,
 * SCALCAL_E_ARGUMENT when the pose has no sample. */
scalcal_status scalcal_pose_set_append(scalcal_pose_set* set, const scalcal_pose* pose);

/* The mean of pose i in raw units (origin + ref + mean), and relative to the origin (ref + mean). */
void scalcal_pose_mean(const scalcal_pose_set* set, uint32_t i, scalcal_real mean[3]);
void scalcal_pose_mean_relative(const scalcal_pose_set* set, uint32_t i, scalcal_real mean[3]);

/* The Euclidean norm over the three axes of the per-axis population variances (scatter / count):
 * the statistic the still-pose detector thresholds (units squared). */
scalcal_real scalcal_pose_variance_norm(const scalcal_pose* pose);

#endif
