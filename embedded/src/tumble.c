/* The tumbling accumulator (scalcal/tumble.h): every valid sample into one of at most `capacity`
 * cells, kept small by Ward's merging, and the second differences that give one sample's noise. */
#include "scalcal/tumble.h"

#include <string.h>

#include "internal.h"

static const int kPair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};

scalcal_status scalcal_tumble_init(scalcal_tumble* t, scalcal_pose_set* cells, scalcal_real adc_min,
                                   scalcal_real adc_max) {
  if (!t || !cells || !cells->poses || cells->capacity < 2) return SCALCAL_E_ARGUMENT;
  if (!sc_finite(adc_min) || !sc_finite(adc_max)) return SCALCAL_E_ARGUMENT;
  memset(t, 0, sizeof *t);
  t->adc_min = adc_min, t->adc_max = adc_max;
  t->pair_cost = (scalcal_real)INFINITY;
  scalcal_pose_set_init(cells, cells->poses, cells->capacity);
  return SCALCAL_OK;
}

void scalcal_tumble_gate(scalcal_tumble* t, const scalcal_calibration* cal, scalcal_real limit) {
  t->gate = cal;
  t->gate_limit = limit;
}

void scalcal_tumble_noise(const scalcal_tumble* t, scalcal_real noise[3]) {
  int k;
  for (k = 0; k < 3; ++k) noise[k] = t->nd ? SC_SQRT(t->d2[k] / 6) : 0;
}

static scalcal_real distance2(const scalcal_real w[3], const scalcal_real a[3], const scalcal_real b[3]) {
  const scalcal_real d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
  return w[0] * d0 * d0 + w[1] * d1 * d1 + w[2] * d2 * d2;
}

/* The metric: each axis in units of its noise so far (1 before any second difference). In raw
 * counts the noise is anisotropic wherever the gains differ; a boundary between cells then selects
 * samples by a noise component with a radial part, which biased the QMC5883L-like meter's scale
 * deviations by 0.4-0.8 % at every number of cells (tests/tumble_test.c, test_anisotropic). */
static void metric(const scalcal_tumble* t, scalcal_real w[3]) {
  int k;
  for (k = 0; k < 3; ++k) w[k] = t->nd && t->d2[k] > 0 ? 1 / t->d2[k] : 1;
}

/* Ward's cost of merging cells a and b: the scatter their union adds. */
static scalcal_real ward(const scalcal_real w[3], const scalcal_pose* a, const scalcal_pose* b) {
  const scalcal_real na = (scalcal_real)a->count, nb = (scalcal_real)b->count;
  return na * nb / (na + nb) * distance2(w, a->mean, b->mean);
}

static void cheapest_pair(scalcal_tumble* t, const scalcal_pose_set* cells) {
  uint32_t i, j;
  scalcal_real w[3];
  metric(t, w);
  t->pair_cost = (scalcal_real)INFINITY;
  for (i = 0; i < cells->count; ++i)
    for (j = i + 1; j < cells->count; ++j) {
      const scalcal_real c = ward(w, &cells->poses[i], &cells->poses[j]);
      if (c < t->pair_cost) t->pair_cost = c, t->pair_a = i, t->pair_b = j;
    }
}

/* Chan's update: a += b. */
static void merge(scalcal_pose* a, const scalcal_pose* b) {
  const scalcal_real n = (scalcal_real)a->count + (scalcal_real)b->count;
  const scalcal_real fb = (scalcal_real)b->count / n, fab = (scalcal_real)a->count * fb;
  scalcal_real delta[3];
  int k;
  for (k = 0; k < 3; ++k) delta[k] = b->mean[k] - a->mean[k];
  for (k = 0; k < 6; ++k) a->scatter[k] += b->scatter[k] + delta[kPair[k][0]] * delta[kPair[k][1]] * fab;
  for (k = 0; k < 3; ++k) a->mean[k] += delta[k] * fb;
  a->count += b->count;
}

/* Welford's update of a cell by one sample r (relative to the origin). */
static void add(scalcal_pose* p, const scalcal_real r[3]) {
  scalcal_real delta[3];
  int k;
  p->count += 1;
  for (k = 0; k < 3; ++k) {
    delta[k] = r[k] - p->mean[k];
    p->mean[k] += delta[k] / (scalcal_real)p->count;
  }
  for (k = 0; k < 6; ++k) p->scatter[k] += delta[kPair[k][0]] * (r[kPair[k][1]] - p->mean[kPair[k][1]]);
}

static void fresh(scalcal_pose* p, const scalcal_real r[3]) {
  memset(p, 0, sizeof *p);
  p->count = 1;
  memcpy(p->mean, r, sizeof p->mean);
}

static int valid(const scalcal_tumble* t, const scalcal_real x[3]) {
  int k;
  for (k = 0; k < 3; ++k) {
    if (!sc_finite(x[k])) return 0;
    if (t->adc_min < t->adc_max && !(x[k] > t->adc_min && x[k] < t->adc_max)) return 0;
  }
  return 1;
}

/* The gate: the sample's corrected modulus against the calibration's magnitude. */
static int disturbed(const scalcal_tumble* t, const scalcal_real x[3]) {
  const scalcal_calibration* c = t->gate;
  scalcal_real d[3], y[3];
  int k;
  if (!c) return 0;
  for (k = 0; k < 3; ++k) d[k] = x[k] - c->offset[k];
  for (k = 0; k < 3; ++k) y[k] = c->matrix[k][0] * d[0] + c->matrix[k][1] * d[1] + c->matrix[k][2] * d[2];
  return !(SC_FABS(sc_norm3(y) / c->magnitude - 1) <= t->gate_limit);
}

int scalcal_tumble_push(scalcal_tumble* t, scalcal_pose_set* cells, const scalcal_real sample[3]) {
  scalcal_real r[3], w[3], best = (scalcal_real)INFINITY;
  uint32_t i, nearest = 0;
  int k;
  if (!valid(t, sample)) {
    t->invalid++, t->run = 0;
    return 0;
  }
  if (!cells->has_origin) {
    memcpy(cells->origin, sample, sizeof cells->origin);
    cells->has_origin = 1;
  }
  for (k = 0; k < 3; ++k) r[k] = sample[k] - cells->origin[k];
  /* The noise from every valid run, gated or not: a disturbance moves slowly, the noise does not. */
  if (t->run >= 2) { /* a running mean, not a sum: a float sum of hours of samples stops growing */
    t->nd++;
    for (k = 0; k < 3; ++k) {
      const scalcal_real d = r[k] - 2 * t->previous[1][k] + t->previous[0][k];
      t->d2[k] += (d * d - t->d2[k]) / (scalcal_real)t->nd;
    }
  }
  memcpy(t->previous[0], t->previous[1], sizeof t->previous[0]);
  memcpy(t->previous[1], r, sizeof t->previous[1]);
  if (t->run < 2) t->run++;
  if (disturbed(t, sample)) {
    t->disturbed++;
    return 0;
  }
  t->samples++;
  if (cells->count < cells->capacity) { /* every sample its own cell until the set is full */
    fresh(&cells->poses[cells->count++], r);
    if (cells->count == cells->capacity) cheapest_pair(t, cells);
    return 1;
  }
  metric(t, w);
  for (i = 0; i < cells->count; ++i) { /* the cell the sample adds least scatter to */
    const scalcal_real n = (scalcal_real)cells->poses[i].count;
    const scalcal_real c = n / (n + 1) * distance2(w, cells->poses[i].mean, r);
    if (c < best) best = c, nearest = i;
  }
  if (best <= t->pair_cost) {
    add(&cells->poses[nearest], r);
    /* That cell's pair costs changed: the threshold stays as it was until the next merge (it only
     * decides where a sample goes; no sample is lost either way). */
    return 1;
  }
  /* Cheaper to merge the cheapest pair and give the sample a cell of its own. */
  merge(&cells->poses[t->pair_a], &cells->poses[t->pair_b]);
  fresh(&cells->poses[t->pair_b], r);
  t->merges++;
  cheapest_pair(t, cells);
  return 1;
}
