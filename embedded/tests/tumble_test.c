/* Test side only (host, float and double): the tumbling mode (scalcal/tumble.h) on a simulated
 * magnetometer of known truth turned continuously (great circles at 60 degrees per second through
 * random directions, 50 Hz, as `scalcal simulate --tumble` turns it), with soft iron of 5-10 %: the
 * truth within 5 standard errors with the field known and unknown and at several capacities; every
 * sample in exactly one cell; NaN, infinity and saturation counted and left out; disturbances left
 * out by the gated second pass; a meter turned about one axis only, and one never turned, refused;
 * arguments out of range refused. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "scalcal/fit.h"
#include "scalcal/tumble.h"

static unsigned long long rng_state = 0x2545F4914F6CDD1Dull;
static double uniform(void) {
  rng_state ^= rng_state >> 12, rng_state ^= rng_state << 25, rng_state ^= rng_state >> 27;
  return (double)((rng_state * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}
static double gaussian(void) { return sqrt(-2 * log(1 - uniform())) * cos(6.283185307179586 * uniform()); }

static void normalise(double v[3]) {
  const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  v[0] /= n, v[1] /= n, v[2] /= n;
}

/* raw = offset + G |I| d + noise, G = diag(k) Phi (Phi symmetric, phi = gamma / 2), in counts: 20
 * counts per uT in a field of 48 uT, noise 0.5 % of the field per axis. */
typedef struct {
  double offset[3], k[3], gamma[3], G[9], magnitude, noise, axis_noise[3];
} meter;

static void make_meter(meter* m) {
  const double pxy = 0.04, pyz = -0.05, pzx = 0.03;
  const double P[9] = {sqrt(1 - pxy * pxy - pzx * pzx), pxy, pzx, pxy, sqrt(1 - pxy * pxy - pyz * pyz), pyz, pzx, pyz,
                       sqrt(1 - pzx * pzx - pyz * pyz)};
  int i;
  m->offset[0] = 96.5, m->offset[1] = -150.25, m->offset[2] = 61.0;
  m->k[0] = 20 * 1.10, m->k[1] = 20 * 0.92, m->k[2] = 20 * 1.05;
  m->gamma[0] = 2 * pxy, m->gamma[1] = 2 * pyz, m->gamma[2] = 2 * pzx;
  for (i = 0; i < 9; ++i) m->G[i] = m->k[i / 3] * P[i];
  m->magnitude = 48;
  m->noise = 0.005 * 48 * 20;
  m->axis_noise[0] = m->axis_noise[1] = m->axis_noise[2] = m->noise;
}

/* The QMC5883L of ../shared/data as the CLI fits it: gains 1075, 740.5, 1603 counts per unit field
 * (a factor 2.2 apart), offsets of thousands of counts, noise 5.6 % of the field on every axis in
 * its own gain (isotropic once corrected, anisotropic in counts). */
static void make_qmc_like(meter* m) {
  const double pxy = 0.03, pyz = 0.05, pzx = 0.005;
  const double P[9] = {sqrt(1 - pxy * pxy - pzx * pzx), pxy, pzx, pxy, sqrt(1 - pxy * pxy - pyz * pyz), pyz, pzx, pyz,
                       sqrt(1 - pzx * pzx - pyz * pyz)};
  int i;
  m->offset[0] = 6154, m->offset[1] = 254, m->offset[2] = 3447;
  m->k[0] = 1075, m->k[1] = 740.5, m->k[2] = 1603;
  m->gamma[0] = 2 * pxy, m->gamma[1] = 2 * pyz, m->gamma[2] = 2 * pzx;
  for (i = 0; i < 9; ++i) m->G[i] = m->k[i / 3] * P[i];
  m->magnitude = 1;
  m->noise = 0.056;
  for (i = 0; i < 3; ++i) m->axis_noise[i] = 0.056 * m->k[i];
}

static void measure(const meter* m, const double d[3], double disturbance, scalcal_real x[3]) {
  int i;
  for (i = 0; i < 3; ++i)
    x[i] = (scalcal_real)(m->offset[i] + m->magnitude * (m->G[3 * i] * d[0] + m->G[3 * i + 1] * d[1] +
                                                         m->G[3 * i + 2] * d[2]) +
                          disturbance + m->axis_noise[i] * gaussian());
}

/* The tumble: `samples` at 50 Hz along great circles at 60 deg/s; axis_only turns about z only.
 * Disturbed: two stretches of 2 s (at 30 % and 60 % of the stream) where a field of up to 30 % of
 * |I| passes along x (a half sine), as `scalcal simulate --disturbances` makes them. bad: every
 * 97th sample NaN, infinite or at the rail. Returns the samples pushed. */
static int tumble(const meter* m, int samples, int axis_only, int disturbed, int bad, scalcal_tumble* t,
                  scalcal_pose_set* cells, const scalcal_calibration* gate) {
  const double step = 60.0 / 50 * 3.141592653589793 / 180;
  double d[3] = {1, 0, 0}, to[3];
  int s, k, left = 0;
  scalcal_tumble_init(t, cells, bad ? -30000 : 0, bad ? 30000 : 0);
  if (gate) scalcal_tumble_gate(t, gate, 5 * gate->noise / gate->magnitude);
  for (s = 0; s < samples; ++s) {
    scalcal_real x[3];
    double a[3], dot, disturbance = 0;
    if (left <= 0) { /* the next target: a random direction (in the x-y plane when axis_only) */
      for (k = 0; k < 3; ++k) to[k] = gaussian();
      if (axis_only) to[2] = 0;
      normalise(to);
      left = 1 + (int)(acos(fmax(-1, fmin(1, d[0] * to[0] + d[1] * to[1] + d[2] * to[2]))) / step);
    }
    /* Rotate d towards `to` by one step: d cos + a sin, a the unit tangent towards `to`. */
    dot = d[0] * to[0] + d[1] * to[1] + d[2] * to[2];
    for (k = 0; k < 3; ++k) a[k] = to[k] - dot * d[k];
    if (a[0] * a[0] + a[1] * a[1] + a[2] * a[2] > 1e-20) {
      normalise(a);
      for (k = 0; k < 3; ++k) d[k] = d[k] * cos(step) + a[k] * sin(step);
      normalise(d);
    }
    --left;
    if (disturbed) {
      const int first[2] = {samples * 3 / 10, samples * 6 / 10};
      for (k = 0; k < 2; ++k)
        if (s >= first[k] && s < first[k] + 100)
          disturbance = 0.3 * m->magnitude * m->k[0] * sin(3.141592653589793 * (s - first[k]) / 100.0);
    }
    measure(m, d, disturbance, x);
    if (bad && s % 97 == 0) x[s % 3] = (scalcal_real)(s % 2 ? NAN : s % 3 ? INFINITY : 30000);
    scalcal_tumble_push(t, cells, x);
  }
  return samples;
}

static scalcal_pose storage[256];

/* Every parameter within 5 standard errors of the truth; the noise within 10 % of the truth's. */
static void check_truth(const meter* m, const scalcal_calibration* c, int magnitude_auto, const char* what) {
  int k;
  const double noise = magnitude_auto ? 0.005 : 0.005 * m->magnitude;
  for (k = 0; k < 3; ++k) {
    const double gain = magnitude_auto ? m->k[k] * m->magnitude : m->k[k];
    CHECK(fabs(c->offset[k] - m->offset[k]) < 5 * c->bias_std[k], "%s: offset %d %g truth %g se %g", what, k,
          (double)c->offset[k], m->offset[k], (double)c->bias_std[k]);
    CHECK(fabs(c->nonorthogonality[k] - m->gamma[k]) < 5 * c->nonorthogonality_std[k],
          "%s: gamma %d %g truth %g se %g", what, k, (double)c->nonorthogonality[k], m->gamma[k],
          (double)c->nonorthogonality_std[k]);
    CHECK(fabs(c->gain[k] - gain) < 5 * c->gain_std[k], "%s: gain %d %g truth %g se %g", what, k, (double)c->gain[k],
          gain, (double)c->gain_std[k]);
  }
  CHECK(fabs(c->noise / noise - 1) < 0.1, "%s: noise %g, truth %g", what, (double)c->noise, noise);
}

static void test_truth(void) {
  static const uint32_t capacities[4] = {16, 64, 128, 256};
  meter m;
  scalcal_tumble t;
  scalcal_pose_set cells;
  scalcal_fit_options o;
  scalcal_calibration c;
  scalcal_fit_report r;
  scalcal_status s;
  char what[96];
  int i, magnitude_auto;
  uint32_t k, total;
  make_meter(&m);
  for (i = 0; i < 4; ++i)
    for (magnitude_auto = 0; magnitude_auto < 2; ++magnitude_auto) {
      sprintf(what, "%u cells, field %s", (unsigned)capacities[i], magnitude_auto ? "unknown" : "known");
      scalcal_pose_set_init(&cells, storage, capacities[i]);
      tumble(&m, 6000, 0, 0, 0, &t, &cells, 0);
      for (total = 0, k = 0; k < cells.count; ++k) total += cells.poses[k].count;
      CHECK(cells.count == capacities[i] && total == 6000 && t.samples == 6000 && t.invalid == 0,
            "%s: %u cells holding %u samples (%u pushed)", what, (unsigned)cells.count, (unsigned)total,
            (unsigned)t.samples);
      scalcal_fit_options_default(&o);
      o.magnitude = (scalcal_real)m.magnitude;
      o.magnitude_auto = magnitude_auto;
      o.tumble = &t;
      s = scalcal_fit(&cells, &o, &c, &r);
      CHECK(s == SCALCAL_OK && r.model == SCALCAL_MODEL_PAPER9 && r.noise_source == SCALCAL_NOISE_DIFFERENCES,
            "%s: %s, model %d", what, scalcal_status_text(s), (int)r.model);
      if (s == SCALCAL_OK) check_truth(&m, &c, magnitude_auto, what);
      CHECK(s != SCALCAL_OK || c.samples == 6000, "%s: %u samples", what, (unsigned)c.samples);
    }
  /* The still-pose fit on the same cells (no tumble) fits their means, which lie inside the sphere
   * by their spread: it must not agree (what the second-order term is for). */
  o.tumble = 0;
  o.magnitude_auto = 0;
  scalcal_pose_set_init(&cells, storage, 64);
  tumble(&m, 6000, 0, 0, 0, &t, &cells, 0);
  s = scalcal_fit(&cells, &o, &c, &r);
  CHECK(s != SCALCAL_OK || fabs(c.gain[0] / m.k[0] - 1) > 0.005, "cells fitted as still poses: %s, gain %g, truth %g",
        scalcal_status_text(s), (double)c.gain[0], m.k[0]);
}

/* NaN, infinity and samples at the rail: counted, left out, and the calibration still right. */
static void test_bad_samples(void) {
  meter m;
  scalcal_tumble t;
  scalcal_pose_set cells;
  scalcal_fit_options o;
  scalcal_calibration c;
  scalcal_status s;
  make_meter(&m);
  scalcal_pose_set_init(&cells, storage, 64);
  tumble(&m, 6000, 0, 0, 1, &t, &cells, 0);
  CHECK(t.invalid == 62 && t.samples == 6000 - 62, "bad samples: %u invalid, %u used", (unsigned)t.invalid,
        (unsigned)t.samples);
  scalcal_fit_options_default(&o);
  o.magnitude = (scalcal_real)m.magnitude;
  o.tumble = &t;
  s = scalcal_fit(&cells, &o, &c, 0);
  CHECK(s == SCALCAL_OK, "bad samples: %s", scalcal_status_text(s));
  if (s == SCALCAL_OK) check_truth(&m, &c, 0, "bad samples");
}

static double distance_to(const scalcal_real a[3], const double b[3]) {
  return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/* Two disturbances of 30 % of the field (200 samples of 6000): the first pass is pulled off; each
 * further pass over the same tumble, gated at 5 times the previous calibration's noise, leaves out
 * more of them and fewer good samples, as the host's rounds do; after the fourth the offsets are
 * less than half as far from the truth and the truth within 5 standard errors. */
static void test_disturbances(void) {
  meter m;
  scalcal_tumble t;
  scalcal_pose_set cells;
  scalcal_fit_options o;
  scalcal_calibration previous, c;
  scalcal_status s;
  unsigned long long seed;
  double first_off;
  int pass;
  make_meter(&m);
  scalcal_fit_options_default(&o);
  o.magnitude = (scalcal_real)m.magnitude;
  o.tumble = &t;
  scalcal_pose_set_init(&cells, storage, 64);
  seed = rng_state;
  tumble(&m, 6000, 0, 1, 0, &t, &cells, 0);
  s = scalcal_fit(&cells, &o, &c, 0);
  CHECK(s == SCALCAL_OK, "disturbed, first pass: %s", scalcal_status_text(s));
  first_off = distance_to(c.offset, m.offset);
  for (pass = 2; pass <= 4 && s == SCALCAL_OK; ++pass) {
    previous = c;
    rng_state = seed; /* the same motion and noise again: another pass over the same tumble */
    tumble(&m, 6000, 0, 1, 0, &t, &cells, &previous);
    s = scalcal_fit(&cells, &o, &c, 0);
    CHECK(s == SCALCAL_OK, "disturbed, pass %d: %s", pass, scalcal_status_text(s));
  }
  CHECK(t.disturbed >= 150 && t.disturbed <= 300, "disturbed, last pass: %u samples left out (200 disturbed)",
        (unsigned)t.disturbed);
  CHECK(s != SCALCAL_OK || distance_to(c.offset, m.offset) < first_off / 2,
        "disturbed: the offset %g counts from the truth after the passes, %g after the first", distance_to(c.offset, m.offset),
        first_off);
  if (s == SCALCAL_OK) check_truth(&m, &c, 0, "disturbed, last pass");
}

/* Turned about one axis only (every direction in one plane), or never turned: no calibration. */
static void test_refused(void) {
  meter m;
  scalcal_tumble t;
  scalcal_pose_set cells;
  scalcal_fit_options o;
  scalcal_calibration c;
  scalcal_status s;
  int magnitude_auto, k;
  make_meter(&m);
  for (magnitude_auto = 0; magnitude_auto < 2; ++magnitude_auto) {
    scalcal_fit_options_default(&o);
    o.magnitude = (scalcal_real)m.magnitude;
    o.magnitude_auto = magnitude_auto;
    o.tumble = &t;
    scalcal_pose_set_init(&cells, storage, 64);
    tumble(&m, 6000, 1, 0, 0, &t, &cells, 0);
    s = scalcal_fit(&cells, &o, &c, 0);
    CHECK(s == SCALCAL_E_NOT_IDENTIFIABLE || s == SCALCAL_E_NO_START, "turned about z only (field %s): %s",
          magnitude_auto ? "unknown" : "known", scalcal_status_text(s));
    scalcal_tumble_init(&t, &cells, 0, 0);
    for (k = 0; k < 3000; ++k) {
      const double d[3] = {0.6, 0, 0.8};
      scalcal_real x[3];
      measure(&m, d, 0, x);
      scalcal_tumble_push(&t, &cells, x);
    }
    s = scalcal_fit(&cells, &o, &c, 0);
    CHECK(s != SCALCAL_OK, "never turned (field %s): %s", magnitude_auto ? "unknown" : "known",
          scalcal_status_text(s));
  }
  scalcal_pose_set_init(&cells, storage, 1);
  CHECK(scalcal_tumble_init(&t, &cells, 0, 0) == SCALCAL_E_ARGUMENT, "capacity 1");
  scalcal_pose_set_init(&cells, storage, 64);
  CHECK(scalcal_tumble_init(&t, &cells, (scalcal_real)NAN, 0) == SCALCAL_E_ARGUMENT, "NaN rail");
  CHECK(scalcal_tumble_init(0, &cells, 0, 0) == SCALCAL_E_ARGUMENT, "null accumulator");
}

/* A meter whose gains differ by a factor 2.2 with 5.6 % noise (the QMC5883L's): the cells were once
 * formed by Euclidean distance in counts, where the noise is anisotropic; a cell's boundary then
 * selects samples by a noise component with a radial part, which biased the scale deviations by
 * 0.4-0.8 % (6-10 of the CLI's standard errors) whatever the number of cells. Distances in units of
 * each axis's noise remove it. The scale deviations (relative to their geometric mean: the noise
 * inflates every modulus alike by about its square, in the CLI's fit as here) and the
 * non-orthogonality within 5 standard errors of the truth, and the offsets. */
static void test_anisotropic(void) {
  meter m;
  scalcal_tumble t;
  scalcal_pose_set cells;
  scalcal_fit_options o;
  scalcal_calibration c;
  scalcal_status s;
  double mean;
  int k;
  make_qmc_like(&m);
  scalcal_pose_set_init(&cells, storage, 64);
  tumble(&m, 20000, 0, 0, 0, &t, &cells, 0);
  scalcal_fit_options_default(&o);
  o.magnitude_auto = 1;
  o.tumble = &t;
  s = scalcal_fit(&cells, &o, &c, 0);
  CHECK(s == SCALCAL_OK, "anisotropic: %s", scalcal_status_text(s));
  if (s != SCALCAL_OK) return;
  mean = cbrt(m.k[0] * m.k[1] * m.k[2]);
  for (k = 0; k < 3; ++k) {
    CHECK(fabs(c.scale_deviation[k] - (m.k[k] / mean - 1)) < 5 * c.scale_deviation_std[k],
          "anisotropic: scale deviation %d %g truth %g se %g", k, (double)c.scale_deviation[k], m.k[k] / mean - 1,
          (double)c.scale_deviation_std[k]);
    CHECK(fabs(c.nonorthogonality[k] - m.gamma[k]) < 5 * c.nonorthogonality_std[k],
          "anisotropic: gamma %d %g truth %g se %g", k, (double)c.nonorthogonality[k], m.gamma[k],
          (double)c.nonorthogonality_std[k]);
    CHECK(fabs(c.offset[k] - m.offset[k]) < 5 * c.bias_std[k], "anisotropic: offset %d %g truth %g se %g", k,
          (double)c.offset[k], m.offset[k], (double)c.bias_std[k]);
  }
}

int main(void) {
  test_truth();
  test_anisotropic();
  test_bad_samples();
  test_disturbances();
  test_refused();
  printf("%s tumbling tests (%s): %d failures\n", failures ? "FAILED" : "passed",
         sizeof(scalcal_real) == 8 ? "double" : "float", failures);
  return failures ? 1 : 0;
}
