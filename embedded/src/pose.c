/* Per-pose sums (scalcal/pose.h): Welford's update sample by sample, Chan's for merging two poses. */
#include "scalcal/pose.h"

#include "internal.h"
#include <string.h>

scalcal_status scalcal_pose_set_init(scalcal_pose_set* set, scalcal_pose* storage, uint32_t capacity) {
  if (!set || !storage || capacity == 0) return SCALCAL_E_ARGUMENT;
  memset(set, 0, sizeof *set);
  set->poses = storage;
  set->capacity = capacity;
  return SCALCAL_OK;
}

void scalcal_pose_clear(scalcal_pose* pose) { memset(pose, 0, sizeof *pose); }

/* The product terms of the scatter, in the order xx, yy, zz, xy, yz, zx. */
static const int kPair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};

void scalcal_pose_add(scalcal_pose_set* set, scalcal_pose* pose, const scalcal_real sample[3], uint32_t index) {
  scalcal_real e[3], delta[3];
  int k;
  if (!set->has_origin) {
    for (k = 0; k < 3; ++k) set->origin[k] = sample[k];
    set->has_origin = 1;
  }
  if (pose->count == 0) {
    for (k = 0; k < 3; ++k) pose->ref[k] = sample[k] - set->origin[k];
    pose->first = index;
  }
  pose->last = index;
  pose->count += 1;
  /* Welford: the deviation from the pose's first sample is small, so float keeps its digits. */
  for (k = 0; k < 3; ++k) {
    e[k] = (sample[k] - set->origin[k]) - pose->ref[k];
    delta[k] = e[k] - pose->mean[k];
    pose->mean[k] += delta[k] / (scalcal_real)pose->count;
  }
  for (k = 0; k < 6; ++k) pose->scatter[k] += delta[kPair[k][0]] * (e[kPair[k][1]] - pose->mean[kPair[k][1]]);
}

void scalcal_pose_merge(scalcal_pose* into, const scalcal_pose* from) {
  scalcal_real delta[3], n, fb, fab;
  int k;
  if (from->count == 0) return;
  if (into->count == 0) {
    *into = *from;
    return;
  }
  /* Chan et al.: the means' difference taken as (ref_b - ref_a) + (mean_b - mean_a), both small. */
  n = (scalcal_real)into->count + (scalcal_real)from->count;
  fb = (scalcal_real)from->count / n;
  fab = (scalcal_real)into->count * fb;
  for (k = 0; k < 3; ++k) delta[k] = (from->ref[k] - into->ref[k]) + (from->mean[k] - into->mean[k]);
  for (k = 0; k < 6; ++k)
    into->scatter[k] += from->scatter[k] + delta[kPair[k][0]] * delta[kPair[k][1]] * fab;
  for (k = 0; k < 3; ++k) into->mean[k] += delta[k] * fb;
  into->count += from->count;
  if (from->first < into->first) into->first = from->first;
  if (from->last > into->last) into->last = from->last;
}

scalcal_status scalcal_pose_set_append(scalcal_pose_set* set, const scalcal_pose* pose) {
  if (!set || !pose || pose->count == 0) return SCALCAL_E_ARGUMENT;
  if (set->count >= set->capacity) return SCALCAL_E_FULL;
  set->poses[set->count++] = *pose;
  return SCALCAL_OK;
}

void scalcal_pose_mean_relative(const scalcal_pose_set* set, uint32_t i, scalcal_real mean[3]) {
  const scalcal_pose* p = &set->poses[i];
  int k;
  for (k = 0; k < 3; ++k) mean[k] = p->ref[k] + p->mean[k];
}

void scalcal_pose_mean(const scalcal_pose_set* set, uint32_t i, scalcal_real mean[3]) {
  const scalcal_pose* p = &set->poses[i];
  int k;
  for (k = 0; k < 3; ++k) mean[k] = set->origin[k] + (p->ref[k] + p->mean[k]);
}

scalcal_real scalcal_pose_variance_norm(const scalcal_pose* pose) {
  scalcal_real v[3], s = 0;
  int k;
  if (pose->count == 0) return 0;
  for (k = 0; k < 3; ++k) {
    v[k] = pose->scatter[k] / (scalcal_real)pose->count;
    if (v[k] < 0) v[k] = 0;
    s += v[k] * v[k];
  }
  return SC_SQRT(s);
}
