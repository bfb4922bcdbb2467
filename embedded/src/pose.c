/* Per-pose sums (scalcal/pose.h): Welford's update sample by sample, Chan's for merging two sums. */
#include "scalcal/pose.h"

#include <string.h>

#include "internal.h"

scalcal_status scalcal_pose_set_init(scalcal_pose_set* set, scalcal_pose* storage, uint32_t capacity) {
  if (!set || !storage || capacity == 0) return SCALCAL_E_ARGUMENT;
  memset(set, 0, sizeof *set);
  set->poses = storage;
  set->capacity = capacity;
  return SCALCAL_OK;
}

void scalcal_pose_sum_clear(scalcal_pose_sum* sum) { memset(sum, 0, sizeof *sum); }

/* The product terms of the scatter, in the order xx, yy, zz, xy, yz, zx. */
static const int kPair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};

void scalcal_pose_sum_add(scalcal_pose_set* set, scalcal_pose_sum* sum, const scalcal_real sample[3], uint32_t index) {
  scalcal_real e[3], delta[3];
  int k;
  if (!set->has_origin) {
    for (k = 0; k < 3; ++k) set->origin[k] = sample[k];
    set->has_origin = 1;
  }
  if (sum->count == 0) {
    for (k = 0; k < 3; ++k) sum->ref[k] = sample[k] - set->origin[k];
    sum->first = index;
  }
  sum->last = index;
  sum->count += 1;
  /* Welford: the deviation from the pose's first sample is small, so float keeps its digits. */
  for (k = 0; k < 3; ++k) {
    e[k] = (sample[k] - set->origin[k]) - sum->ref[k];
    delta[k] = e[k] - sum->mean[k];
    sum->mean[k] += delta[k] / (scalcal_real)sum->count;
  }
  for (k = 0; k < 6; ++k) sum->scatter[k] += delta[kPair[k][0]] * (e[kPair[k][1]] - sum->mean[kPair[k][1]]);
}

void scalcal_pose_sum_merge(scalcal_pose_sum* into, const scalcal_pose_sum* from) {
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
  for (k = 0; k < 6; ++k) into->scatter[k] += from->scatter[k] + delta[kPair[k][0]] * delta[kPair[k][1]] * fab;
  for (k = 0; k < 3; ++k) into->mean[k] += delta[k] * fb;
  into->count += from->count;
  if (from->first < into->first) into->first = from->first;
  if (from->last > into->last) into->last = from->last;
}

scalcal_real scalcal_pose_sum_variance_norm(const scalcal_pose_sum* sum) {
  scalcal_real v, s = 0;
  int k;
  if (sum->count == 0) return 0;
  for (k = 0; k < 3; ++k) {
    v = sum->scatter[k] / (scalcal_real)sum->count;
    if (v < 0) v = 0;
    s += v * v;
  }
  return SC_SQRT(s);
}

scalcal_status scalcal_pose_set_append(scalcal_pose_set* set, const scalcal_pose_sum* sum) {
  scalcal_pose* p;
  int k;
  if (!set || !sum || sum->count == 0) return SCALCAL_E_ARGUMENT;
  if (set->count >= set->capacity) return SCALCAL_E_FULL;
  p = &set->poses[set->count++];
  p->count = sum->count;
  for (k = 0; k < 3; ++k) p->mean[k] = sum->ref[k] + sum->mean[k];
  for (k = 0; k < 6; ++k) p->scatter[k] = sum->scatter[k];
  return SCALCAL_OK;
}

void scalcal_pose_mean_relative(const scalcal_pose_set* set, uint32_t i, scalcal_real mean[3]) {
  int k;
  for (k = 0; k < 3; ++k) mean[k] = set->poses[i].mean[k];
}

void scalcal_pose_mean(const scalcal_pose_set* set, uint32_t i, scalcal_real mean[3]) {
  int k;
  for (k = 0; k < 3; ++k) mean[k] = set->origin[k] + set->poses[i].mean[k];
}
