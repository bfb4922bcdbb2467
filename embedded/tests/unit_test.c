/* Test side only (host, float and double builds): what the library must do with inputs no real log
 * gives. A simulated meter of known truth (offsets, gains, non-orthogonality, noise, motion between
 * poses) must be recovered within its standard errors; fuzzed streams (NaN, infinity, saturation,
 * random values, a stream that never pauses, one that never moves, a full pose set) must end in a
 * clear status and never in a calibration that is wrong or not finite; corrupted flash records
 * must be refused. Exit status 0 when every check passes; each failure is printed. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "scalcal/detector.h"
#include "scalcal/fit.h"
#include "scalcal/guidance.h"
#include "scalcal/rate_table.h"
#include "scalcal/record.h"

/* A seeded generator (xorshift64*) and Gaussian deviates (Box-Muller). */
static unsigned long long rng_state = 88172645463325252ull;
static double uniform(void) {
  rng_state ^= rng_state >> 12, rng_state ^= rng_state << 25, rng_state ^= rng_state >> 27;
  return (double)((rng_state * 2685821657736338717ull) >> 11) / 9007199254740992.0;
}
static double gaussian(void) { return sqrt(-2 * log(1 - uniform())) * cos(6.283185307179586 * uniform()); }

/* The simulated meter: raw = offset + G I with G = diag(k) Phi (Phi symmetric off the diagonal), in
 * counts; the truth every fit is checked against. */
typedef struct {
  double offset[3], G[9], k[3], gamma[3], noise, magnitude;
} meter;

static void make_meter(meter* m, double magnitude, double gain, double noise) {
  const double phi_xy = 0.004, phi_yz = -0.006, phi_zx = 0.003;
  const double P[9] = {sqrt(1 - phi_xy * phi_xy - phi_zx * phi_zx), phi_xy, phi_zx, phi_xy,
                       sqrt(1 - phi_xy * phi_xy - phi_yz * phi_yz), phi_yz, phi_zx, phi_yz,
                       sqrt(1 - phi_zx * phi_zx - phi_yz * phi_yz)};
  int i;
  m->offset[0] = 512.25, m->offset[1] = -301.5, m->offset[2] = 1210.75;
  m->k[0] = gain * 1.012, m->k[1] = gain * 0.991, m->k[2] = gain * 1.004;
  m->gamma[0] = 2 * phi_xy, m->gamma[1] = 2 * phi_yz, m->gamma[2] = 2 * phi_zx;
  for (i = 0; i < 9; ++i) m->G[i] = m->k[i / 3] * P[i];
  m->noise = noise;
  m->magnitude = magnitude;
}

static void measure(const meter* m, const double d[3], scalcal_real out[3]) {
  int i;
  for (i = 0; i < 3; ++i)
    out[i] = (scalcal_real)(m->offset[i] +
                            m->magnitude * (m->G[3 * i] * d[0] + m->G[3 * i + 1] * d[1] + m->G[3 * i + 2] * d[2]) +
                            m->noise * gaussian());
}

static void random_direction(double d[3]) {
  double n;
  do {
    d[0] = 2 * uniform() - 1, d[1] = 2 * uniform() - 1, d[2] = 2 * uniform() - 1;
    n = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  } while (n < 0.1 || n > 1);
  d[0] /= n, d[1] /= n, d[2] /= n;
}

/* A session at 100 Hz: `poses` still poses of `still` samples, each followed by `turn` samples of
 * turning to the next. The hand-held session: 3 s still, 1.5 s turning (session()). */
static void session_of(const meter* m, int poses, int still, int turn, scalcal_detector* det, scalcal_pose_set* set) {
  double from[3], to[3];
  int p, s, k;
  random_direction(from);
  for (p = 0; p < poses; ++p) {
    scalcal_real x[3];
    for (s = 0; s < still; ++s) measure(m, from, x), scalcal_detector_push(det, set, x);
    random_direction(to);
    for (s = 1; s <= turn; ++s) { /* a straight path, renormalised: smooth motion */
      double d[3], n;
      for (k = 0; k < 3; ++k) d[k] = from[k] + (to[k] - from[k]) * s / (double)turn;
      n = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (n < 1e-3) continue;
      for (k = 0; k < 3; ++k) d[k] /= n;
      measure(m, d, x), scalcal_detector_push(det, set, x);
    }
    memcpy(from, to, sizeof from);
  }
  scalcal_detector_finish(det, set);
}

static void session(const meter* m, int poses, scalcal_detector* det, scalcal_pose_set* set) {
  session_of(m, poses, 300, 150, det, set);
}

/* A meter turned most of the time (a magnetometer waved by hand): `poses` pauses of 2.5 s, each
 * followed by 8 s of turning. A window of 1 s is still only when it lies wholly in a pause, so about
 * (10.5 - 1.5) / 10.5 = 86 % of the windows move, and each pause still gives a pose of 1.5 s. */
static void turning_session(const meter* m, int poses, scalcal_detector* det, scalcal_pose_set* set) {
  session_of(m, poses, 250, 800, det, set);
}

static int all_finite(const scalcal_calibration* c) {
  int k;
  for (k = 0; k < 3; ++k)
    if (!isfinite(c->offset[k]) || !isfinite(c->matrix[k][0]) || !isfinite(c->matrix[k][1]) ||
        !isfinite(c->matrix[k][2]))
      return 0;
  return 1;
}

static scalcal_pose storage[SCALCAL_MAX_POSES];
static scalcal_detector det;

static void init_stream(scalcal_pose_set* set, uint32_t capacity) {
  scalcal_detector_options o;
  scalcal_pose_set_init(set, storage, capacity);
  scalcal_detector_options_default(&o, 100);
  scalcal_detector_init(&det, &o);
}

/* The truth recovered: every parameter within 5 standard errors (the errors are the larger of the
 * noise-based and the residual-based, as the host reports them). */
static void test_truth(double magnitude, int magnitude_auto, const char* what) {
  meter m;
  scalcal_pose_set set;
  scalcal_fit_options o;
  scalcal_calibration c;
  scalcal_fit_report r;
  scalcal_status s;
  int k;
  make_meter(&m, magnitude, 1638.4, 2.0);
  init_stream(&set, SCALCAL_MAX_POSES);
  session(&m, 24, &det, &set);
  CHECK(set.count >= 20, "%s: %u poses of 24", what, (unsigned)set.count);
  scalcal_fit_options_default(&o);
  o.magnitude = (scalcal_real)magnitude;
  o.magnitude_auto = magnitude_auto;
  s = scalcal_fit(&set, &o, &c, &r);
  CHECK(s == SCALCAL_OK, "%s: %s", what, scalcal_status_text(s));
  if (s != SCALCAL_OK) return;
  CHECK(r.model == SCALCAL_MODEL_PAPER9, "%s: model %d", what, (int)r.model);
  for (k = 0; k < 3; ++k) {
    const double gain_truth = magnitude_auto ? m.k[k] * magnitude : m.k[k];
    CHECK(fabs(c.offset[k] - m.offset[k]) < 5 * c.bias_std[k], "%s: offset %d %g truth %g se %g", what, k,
          (double)c.offset[k], m.offset[k], (double)c.bias_std[k]);
    CHECK(fabs(c.nonorthogonality[k] - m.gamma[k]) < 5 * c.nonorthogonality_std[k], "%s: gamma %d %g truth %g se %g",
          what, k, (double)c.nonorthogonality[k], m.gamma[k], (double)c.nonorthogonality_std[k]);
    CHECK(fabs(c.gain[k] - gain_truth) < 5 * c.gain_std[k] + 1e-6 * gain_truth, "%s: gain %d %g truth %g se %g", what,
          k, (double)c.gain[k], gain_truth, (double)c.gain_std[k]);
  }
}

/* The between-pose error model: 40 poses of 200 samples whose field's modulus differs from pose to
 * pose by 5e-4 relative (a hand-held pose is never the same twice), 7 times the noise of a pose's mean
 * (2 counts of 1638.4 per g over sqrt(200)). REML must find sigma_b (within 35 %: its relative
 * standard error with 31 degrees of freedom is about 13 %), the model's standard errors must apply
 * and carry the truth within 5 of them; the noise-based alone are 7 times too small for that. */
static void test_between_poses(void) {
  static scalcal_pose_sum pose;
  const double sigma_b = 5e-4;
  meter m;
  scalcal_pose_set set;
  scalcal_fit_options o;
  scalcal_calibration c;
  scalcal_fit_report r;
  scalcal_status s;
  int p, k, n;
  make_meter(&m, 1.0, 1638.4, 2.0);
  scalcal_pose_set_init(&set, storage, SCALCAL_MAX_POSES);
  for (p = 0; p < 40; ++p) {
    double d[3];
    const double scale = 1 + sigma_b * gaussian();
    random_direction(d);
    for (k = 0; k < 3; ++k) d[k] *= scale;
    scalcal_pose_sum_clear(&pose);
    for (n = 0; n < 200; ++n) {
      scalcal_real x[3];
      measure(&m, d, x);
      scalcal_pose_sum_add(&set, &pose, x, (uint32_t)(p * 200 + n));
    }
    scalcal_pose_set_append(&set, &pose);
  }
  scalcal_fit_options_default(&o);
  s = scalcal_fit(&set, &o, &c, &r);
  CHECK(s == SCALCAL_OK && r.model == SCALCAL_MODEL_PAPER9, "between poses: %s model %d", scalcal_status_text(s),
        (int)r.model);
  if (s != SCALCAL_OK) return;
  CHECK(r.error_model == 1, "between poses: the error model does not apply");
  CHECK(fabs(r.between_std / sigma_b - 1) < 0.35, "between poses: sigma_b %g, truth %g", (double)r.between_std,
        sigma_b);
  for (k = 0; k < 3; ++k) {
    CHECK(c.bias_std[k] == r.model_std[k], "between poses: bias %d's error is not the model's", k);
    CHECK(fabs(c.offset[k] - m.offset[k]) < 5 * c.bias_std[k], "between poses: offset %d %g truth %g se %g", k,
          (double)c.offset[k], m.offset[k], (double)c.bias_std[k]);
    CHECK(fabs(c.gain[k] - m.k[k]) < 5 * c.gain_std[k], "between poses: gain %d %g truth %g se %g", k,
          (double)c.gain[k], m.k[k], (double)c.gain_std[k]);
  }
}

/* Bench data: one sample per pose (18 random directions), weighted by samples: the noise comes from
 * the residuals (N - P degrees of freedom) and the truth is recovered within 5 standard errors. */
static void test_single_samples(void) {
  meter m;
  scalcal_pose_set set;
  scalcal_pose_sum p;
  scalcal_fit_options o;
  scalcal_calibration c;
  scalcal_fit_report r;
  scalcal_status s;
  scalcal_real x[3];
  double d[3];
  int i, k;
  make_meter(&m, 9.80665, 1638.4, 2.0);
  scalcal_pose_set_init(&set, storage, SCALCAL_MAX_POSES);
  for (i = 0; i < 18; ++i) {
    random_direction(d);
    measure(&m, d, x);
    scalcal_pose_sum_clear(&p);
    scalcal_pose_sum_add(&set, &p, x, (uint32_t)i);
    scalcal_pose_set_append(&set, &p);
  }
  scalcal_fit_options_default(&o);
  o.magnitude = (scalcal_real)9.80665;
  o.weight_by_samples = 1;
  s = scalcal_fit(&set, &o, &c, &r);
  CHECK(s == SCALCAL_OK && r.noise_source == SCALCAL_NOISE_RESIDUALS && r.dof == 9, "single samples: %s, noise %d",
        scalcal_status_text(s), (int)r.noise_source);
  if (s != SCALCAL_OK) return;
  for (k = 0; k < 3; ++k)
    CHECK(fabs((double)c.offset[k] - m.offset[k]) < 5 * (double)c.bias_std[k], "single samples: offset %d", k);
}

/* Fuzzed streams: every outcome a status; an OK one finite and near the truth. */
static void test_fuzz(void) {
  meter m;
  scalcal_pose_set set;
  scalcal_fit_options o;
  scalcal_calibration c;
  scalcal_fit_report r;
  scalcal_status s;
  scalcal_real x[3];
  double d[3];
  long i;
  int trial, k;
  make_meter(&m, 9.80665, 1638.4, 2.0);
  scalcal_fit_options_default(&o);
  o.magnitude = (scalcal_real)9.80665;

  /* NaN and infinity sprinkled into a good session: counted, the calibration still right. */
  init_stream(&set, SCALCAL_MAX_POSES);
  {
    double from[3];
    int p;
    for (p = 0; p < 24; ++p) {
      random_direction(from);
      for (i = 0; i < 450; ++i) {
        measure(&m, from, x);
        if (i % 97 == 13) x[i % 3] = (scalcal_real)NAN;
        if (i % 131 == 7) x[(i + 1) % 3] = (scalcal_real)INFINITY;
        scalcal_detector_push(&det, &set, x);
      }
    }
    scalcal_detector_finish(&det, &set);
  }
  CHECK(det.invalid > 0, "invalid samples not counted");
  s = scalcal_fit(&set, &o, &c, &r);
  CHECK(s != SCALCAL_OK || (all_finite(&c) && fabs(c.offset[0] - m.offset[0]) < 10 * c.bias_std[0]),
        "NaN/Inf stream: %s offset %g", scalcal_status_text(s), (double)c.offset[0]);

  /* Saturation: one axis pinned at the ADC's rail for whole poses: those samples never count. */
  init_stream(&set, SCALCAL_MAX_POSES);
  det.options.adc_min = -32768, det.options.adc_max = 32767;
  for (i = 0; i < 20000; ++i) {
    random_direction(d);
    x[0] = 32767, x[1] = (scalcal_real)(1000 * d[1]), x[2] = (scalcal_real)(1000 * d[2]);
    scalcal_detector_push(&det, &set, x);
  }
  scalcal_detector_finish(&det, &set);
  CHECK(set.count == 0 && det.invalid == 20000, "saturated: %u poses, %u invalid", (unsigned)set.count,
        (unsigned)det.invalid);

  /* A stream that never pauses: a meter turning smoothly for ten minutes. */
  init_stream(&set, SCALCAL_MAX_POSES);
  for (i = 0; i < 60000; ++i) {
    const double a = 0.011 * (double)i, b = 0.0037 * (double)i;
    d[0] = cos(a) * cos(b), d[1] = sin(a) * cos(b), d[2] = sin(b);
    measure(&m, d, x);
    scalcal_detector_push(&det, &set, x);
  }
  scalcal_detector_finish(&det, &set);
  s = scalcal_fit(&set, &o, &c, &r);
  CHECK(set.count == 0 && scalcal_detector_state(&det) == SCALCAL_STREAM_NO_FLOOR && s == SCALCAL_E_TOO_FEW_POSES,
        "never pauses: %u poses, state %s, fit %s", (unsigned)set.count, scalcal_detector_state_text(&det),
        scalcal_status_text(s));

  /* A stream that never moves: one pose, too few for any model. */
  init_stream(&set, SCALCAL_MAX_POSES);
  d[0] = 0, d[1] = 0, d[2] = 1;
  for (i = 0; i < 60000; ++i) measure(&m, d, x), scalcal_detector_push(&det, &set, x);
  scalcal_detector_finish(&det, &set);
  s = scalcal_fit(&set, &o, &c, &r);
  CHECK(set.count == 1 && s == SCALCAL_E_TOO_FEW_POSES, "never moves: %u poses, fit %s", (unsigned)set.count,
        scalcal_status_text(s));

  /* Random values (white noise of any size from 1e-30 to 1e30, and wild jumps): no calibration. */
  for (trial = 0; trial < 20; ++trial) {
    const double scale = pow(10, 60 * uniform() - 30); /* float squares overflow or underflow at the ends */
    init_stream(&set, SCALCAL_MAX_POSES);
    for (i = 0; i < 20000; ++i) {
      for (k = 0; k < 3; ++k)
        x[k] = (scalcal_real)(scale * (trial % 2 ? gaussian() : (uniform() < 0.01 ? 1e6 : 1) * uniform()));
      scalcal_detector_push(&det, &set, x);
    }
    scalcal_detector_finish(&det, &set);
    s = scalcal_fit(&set, &o, &c, &r);
    CHECK(s != SCALCAL_OK, "random stream %d gave a calibration from %u poses", trial, (unsigned)set.count);
  }

  /* A full set: poses beyond the capacity are dropped and counted, the fit uses the first ones. */
  init_stream(&set, 12);
  session(&m, 24, &det, &set);
  CHECK(set.count == 12 && det.dropped > 0, "capacity 12: %u poses, %u dropped", (unsigned)set.count,
        (unsigned)det.dropped);
  s = scalcal_fit(&set, &o, &c, &r);
  CHECK(s == SCALCAL_OK || s == SCALCAL_E_NOT_IDENTIFIABLE, "capacity 12: %s", scalcal_status_text(s));
}

/* Pose sets no stream gives: one direction, a plane, NaN, and arguments out of range. */
static void test_degenerate(void) {
  meter m;
  scalcal_pose_set set;
  scalcal_pose_sum p;
  scalcal_fit_options o;
  scalcal_calibration c;
  scalcal_fit_report r;
  scalcal_real x[3];
  double d[3];
  int i, s;
  make_meter(&m, 9.80665, 1638.4, 2.0);
  scalcal_fit_options_default(&o);
  o.magnitude = (scalcal_real)9.80665;
  scalcal_pose_set_init(&set, storage, SCALCAL_MAX_POSES);
  for (i = 0; i < 20; ++i) { /* every pose in the x-y plane */
    d[0] = cos(0.3 * i), d[1] = sin(0.3 * i), d[2] = 0;
    scalcal_pose_sum_clear(&p);
    for (s = 0; s < 50; ++s) measure(&m, d, x), scalcal_pose_sum_add(&set, &p, x, 0);
    scalcal_pose_set_append(&set, &p);
  }
  s = scalcal_fit(&set, &o, &c, &r);
  CHECK(s == SCALCAL_E_NOT_IDENTIFIABLE || s == SCALCAL_E_NO_START,
        "plane: %s model %d cond %g off %g %g %g gain %g %g %g", scalcal_status_text(s), r.model, r.condition,
        c.offset[0], c.offset[1], c.offset[2], c.gain[0], c.gain[1], c.gain[2]);
  set.poses[3].mean[1] = (scalcal_real)NAN;
  CHECK(scalcal_fit(&set, &o, &c, &r) == SCALCAL_E_NOT_FINITE, "NaN pose");
  o.magnitude = -1;
  CHECK(scalcal_fit(&set, &o, &c, &r) == SCALCAL_E_ARGUMENT, "negative magnitude");
  CHECK(scalcal_fit(0, &o, &c, &r) == SCALCAL_E_ARGUMENT, "null set");
  o.magnitude = 1;
  o.model = (scalcal_model)7;
  CHECK(scalcal_fit(&set, &o, &c, &r) == SCALCAL_E_ARGUMENT, "model 7");
  o.model = SCALCAL_MODEL_AUTO;
  o.noise = -1;
  CHECK(scalcal_fit(&set, &o, &c, &r) == SCALCAL_E_ARGUMENT, "negative noise");
  o.noise = (scalcal_real)NAN;
  CHECK(scalcal_fit(&set, &o, &c, &r) == SCALCAL_E_ARGUMENT, "NaN noise");
  o.noise = 0;
  {
    scalcal_detector_options dop;
    scalcal_detector_options_default(&dop, 0);
    CHECK(scalcal_detector_init(&det, &dop) == SCALCAL_E_ARGUMENT, "rate 0");
    scalcal_detector_options_default(&dop, (scalcal_real)NAN);
    CHECK(scalcal_detector_init(&det, &dop) == SCALCAL_E_ARGUMENT, "rate NaN");
  }
}

/* The record: a round trip keeps the float32 values; any flipped bit and an erased page are refused. */
static void test_record(void) {
  meter m;
  scalcal_pose_set set;
  scalcal_fit_options o;
  scalcal_calibration c, back;
  scalcal_fit_report r;
  uint8_t rec[SCALCAL_RECORD_SIZE], bad[SCALCAL_RECORD_SIZE];
  uint32_t seq = 0;
  int i, k;
  make_meter(&m, 9.80665, 1638.4, 2.0);
  init_stream(&set, SCALCAL_MAX_POSES);
  session(&m, 24, &det, &set);
  scalcal_fit_options_default(&o);
  o.magnitude = (scalcal_real)9.80665;
  if (scalcal_fit(&set, &o, &c, &r) != SCALCAL_OK) {
    CHECK(0, "record: no calibration to store");
    return;
  }
  CHECK(scalcal_record_write(&c, 7, rec) == SCALCAL_OK, "write");
  CHECK(scalcal_record_read(rec, &back, &seq) == SCALCAL_OK && seq == 7, "read back");
  for (k = 0; k < 3; ++k) {
    CHECK(back.offset[k] == (scalcal_real)(float)c.offset[k], "offset %d", k);
    CHECK(fabs(back.scale_deviation[k] - c.scale_deviation[k]) < 1e-5, "scale deviation %d: %g %g", k,
          (double)back.scale_deviation[k], (double)c.scale_deviation[k]);
    CHECK(fabs(back.nonorthogonality[k] - c.nonorthogonality[k]) < 1e-5, "gamma %d", k);
  }
  CHECK(back.model == c.model && back.positions == c.positions && back.samples == c.samples, "header fields");
  /* The CRC-32 of "123456789" is 0xCBF43926 (the check value of the IEEE polynomial). */
  CHECK(scalcal_crc32((const uint8_t*)"123456789", 9) == 0xCBF43926u, "crc32 check value");
  for (i = 0; i < SCALCAL_RECORD_SIZE * 8; i += 7) {
    memcpy(bad, rec, sizeof bad);
    bad[i / 8] ^= (uint8_t)(1u << (i % 8));
    CHECK(scalcal_record_read(bad, &back, 0) != SCALCAL_OK, "bit %d flipped and accepted", i);
  }
  memset(bad, 0xFF, sizeof bad);
  CHECK(scalcal_record_read(bad, &back, 0) == SCALCAL_E_RECORD, "erased flash accepted");
}

/* Guidance: the six faces twice identify axis6 with efficiency 1 against its limit (the six axis
 * directions attain it: proofs/axis6_limits.md); a program missing -z asks for -z first. */
static void test_guidance(void) {
  static const double faces[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  scalcal_pose_set set;
  scalcal_pose_sum p;
  scalcal_calibration identity;
  scalcal_program_quality q;
  const scalcal_real offset[3] = {0, 0, 0}, matrix[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  uint32_t best;
  scalcal_real after;
  int i, c;
  scalcal_calibration_from_matrix(&identity, SCALCAL_MODEL_AXIS6, offset, matrix, 1, 0, 1);
  scalcal_pose_set_init(&set, storage, SCALCAL_MAX_POSES);
  for (i = 0; i < 12; ++i) {
    scalcal_real x[3];
    x[0] = (scalcal_real)faces[i % 6][0], x[1] = (scalcal_real)faces[i % 6][1], x[2] = (scalcal_real)faces[i % 6][2];
    scalcal_pose_sum_clear(&p);
    scalcal_pose_sum_add(&set, &p, x, 0);
    scalcal_pose_set_append(&set, &p);
  }
  CHECK(scalcal_program_quality_of(&set, &identity, SCALCAL_MODEL_AXIS6, &q) == SCALCAL_OK && q.full_rank, "faces");
  for (c = 0; c < 4; ++c)
    CHECK(fabs(q.efficiency[c] - 1) < 1e-5, "axis6 faces efficiency %d: %.9g", c, (double)q.efficiency[c]);
  /* The faces twice but the last -z: the next is -z by every criterion (the twelve then attain every
   * limit, which no other twelfth direction does). */
  set.count = 11;
  for (c = 0; c < 4; ++c) {
    CHECK(scalcal_next_pose(&set, &identity, SCALCAL_MODEL_AXIS6, (scalcal_criterion)c, scalcal_candidates26, 26, &best,
                            &after) == SCALCAL_OK &&
              best == 5 && fabs(after - q.limit[c]) < 1e-3 * q.limit[c],
          "axis6 next pose by criterion %d: %u (%g)", c, (unsigned)best, (double)after);
  }
  set.count = 2; /* +x, -x: rank-deficient; the next adds what is missing (y or z), never x again */
  CHECK(scalcal_next_pose(&set, &identity, SCALCAL_MODEL_BIAS3, SCALCAL_CRITERION_D, scalcal_candidates26, 26, &best,
                          &after) == SCALCAL_OK &&
            fabs(scalcal_candidates26[best][0]) < 0.1,
        "rank-deficient next pose %u", (unsigned)best);
}

/* A stream that moves most of the time is refused (SCALCAL_E_MOVING) although its pauses make poses
 * enough; the hand-held session (3 s still, 1.5 s turning: (4.5 - 2) / 4.5 = 56 % of its 1 s windows
 * touch motion) is not. */
static void test_moving(void) {
  meter m;
  scalcal_pose_set set;
  scalcal_fit_options o;
  scalcal_calibration c;
  scalcal_status s;
  double share;
  make_meter(&m, 48.0, 1638.4, 2.0);
  scalcal_fit_options_default(&o);
  o.magnitude_auto = 1;
  init_stream(&set, SCALCAL_MAX_POSES);
  turning_session(&m, 24, &det, &set);
  share = (double)set.windows_moving / set.windows_judged;
  CHECK(set.count >= 9, "turning: %u poses (pauses of 2.5 s)", (unsigned)set.count);
  CHECK(share > 0.8 && share < 0.92, "turning: moving share %g (expected 0.86)", share);
  s = scalcal_fit(&set, &o, &c, 0);
  CHECK(s == SCALCAL_E_MOVING, "turning: %s", scalcal_status_text(s));
  init_stream(&set, SCALCAL_MAX_POSES);
  session(&m, 24, &det, &set);
  share = (double)set.windows_moving / set.windows_judged;
  CHECK(share > 0.5 && share < 0.61, "hand-held: moving share %g (expected 0.56)", share);
  s = scalcal_fit(&set, &o, &c, 0);
  CHECK(s == SCALCAL_OK, "hand-held: %s", scalcal_status_text(s));
}

/* A gyro on a rate table through the detector: rests of 3 s (the bias alone) between segments of 10 s
 * at 2 rad/s about 14 axes (the faces' and the corners' of a cube), ramps of 1 s between. The rate-table
 * fit finds 14 segments and 15 rests and the truth within 5 standard errors; the still-pose fit on the
 * same poses does not calibrate (half of them are rests, not of the rate's modulus); a log with only its
 * first rest is refused (SCALCAL_E_NO_RESTS), as is a rate of 0. */
static void rate_table_session(const meter* m, int rests_between, scalcal_pose_set* set) {
  static const double zero[3] = {0, 0, 0};
  double axes[14][3], from[3] = {0, 0, 0};
  int a, s, k;
  const double r3 = 1 / sqrt(3.0);
  for (a = 0; a < 6; ++a) axes[a][0] = axes[a][1] = axes[a][2] = 0, axes[a][a / 2] = a % 2 ? -1 : 1;
  for (a = 0; a < 8; ++a) axes[6 + a][0] = a & 1 ? -r3 : r3, axes[6 + a][1] = a & 2 ? -r3 : r3, axes[6 + a][2] = a & 4 ? -r3 : r3;
  init_stream(set, SCALCAL_MAX_POSES);
  for (a = 0; a <= 14; ++a) {
    scalcal_real x[3];
    if (a == 0 || rests_between) { /* to rest, rest */
      for (s = 1; s <= 100; ++s) {
        double d[3];
        for (k = 0; k < 3; ++k) d[k] = from[k] * (1 - s / 100.0);
        measure(m, d, x), scalcal_detector_push(&det, set, x);
      }
      for (s = 0; s < 300; ++s) measure(m, zero, x), scalcal_detector_push(&det, set, x);
      memcpy(from, zero, sizeof from);
    }
    if (a == 14) break;
    for (s = 1; s <= 100; ++s) { /* to the next rate, then turn at it */
      double d[3];
      for (k = 0; k < 3; ++k) d[k] = from[k] + (axes[a][k] - from[k]) * s / 100.0;
      measure(m, d, x), scalcal_detector_push(&det, set, x);
    }
    for (s = 0; s < 1000; ++s) measure(m, axes[a], x), scalcal_detector_push(&det, set, x);
    memcpy(from, axes[a], sizeof from);
  }
  scalcal_detector_finish(&det, set);
}

static void test_rate_table(void) {
  meter m;
  scalcal_pose_set set;
  scalcal_rate_table_options o;
  scalcal_rate_table_report r;
  scalcal_fit_options fo;
  scalcal_calibration c;
  scalcal_status s;
  int k;
  make_meter(&m, 2.0, 938.7, 2.0); /* counts per rad/s: 16.4 LSB per deg/s */
  rate_table_session(&m, 1, &set);
  scalcal_rate_table_options_default(&o);
  o.rate = 2.0;
  s = scalcal_fit_rate_table(&set, &o, &c, &r);
  CHECK(s == SCALCAL_OK && r.segments == 14 && r.rests == 15 && r.model == SCALCAL_MODEL_PAPER9,
        "rate table: %s, %u segments, %u rests, model %d", scalcal_status_text(s), (unsigned)r.segments,
        (unsigned)r.rests, (int)r.model);
  for (k = 0; s == SCALCAL_OK && k < 3; ++k) {
    CHECK(fabs(c.offset[k] - m.offset[k]) < 5 * c.bias_std[k], "rate table: offset %d %g, true %g (std %g)", k,
          (double)c.offset[k], m.offset[k], (double)c.bias_std[k]);
    CHECK(fabs(c.gain[k] - m.k[k]) < 5 * c.gain_std[k], "rate table: gain %d %g, true %g (std %g)", k,
          (double)c.gain[k], m.k[k], (double)c.gain_std[k]);
    CHECK(fabs(c.nonorthogonality[k] - m.gamma[k]) < 5 * c.nonorthogonality_std[k],
          "rate table: gamma %d %g, true %g (std %g)", k, (double)c.nonorthogonality[k], m.gamma[k],
          (double)c.nonorthogonality_std[k]);
  }
  scalcal_fit_options_default(&fo);
  fo.magnitude = 2.0;
  s = scalcal_fit(&set, &fo, &c, 0);
  CHECK(s != SCALCAL_OK, "rate table fitted as still poses: calibrated");
  o.rate = 0;
  s = scalcal_fit_rate_table(&set, &o, &c, &r);
  CHECK(s == SCALCAL_E_ARGUMENT, "rate table, rate 0: %s", scalcal_status_text(s));
  o.rate = 2.0;
  rate_table_session(&m, 0, &set);
  s = scalcal_fit_rate_table(&set, &o, &c, &r);
  CHECK(s == SCALCAL_E_NO_RESTS, "rate table, one rest: %s (%u poses)", scalcal_status_text(s), (unsigned)set.count);
}

int main(void) {
  test_truth(9.80665, 0, "accelerometer in counts");
  test_truth(48.0, 1, "magnetometer, field unknown");
  test_single_samples();
  test_between_poses();
  test_fuzz();
  test_degenerate();
  test_record();
  test_guidance();
  test_moving(); /* last: the random stream of the tests above stays as it was */
  test_rate_table();
  printf("%s unit tests (%s): %d failures\n", failures ? "FAILED" : "passed",
         sizeof(scalcal_real) == 8 ? "double" : "float", failures);
  return failures ? 1 : 0;
}
