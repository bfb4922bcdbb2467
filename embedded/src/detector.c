/* The streaming still-pose detector (scalcal/detector.h; every rule is stated in README.md). */
#include <string.h>

#include "internal.h"
#include "scalcal/detector.h"

#define HALF (SCALCAL_DETECTOR_BLOCKS / 2)
#define QUIET_BINS 12                             /* 3 x the 5 % quantile: 8 log2(3) = 12.7 bins */
#define MIN_WINDOWS (2 * SCALCAL_DETECTOR_BLOCKS) /* white windows before the floor is trusted */
#define MAX_POSE_SAMPLES 16777216u                /* 2^24: beyond, a float count is no longer exact */
#define MOVING_FACTOR 3 /* a window moves above 3 x the floor (the host's kMovingWindow, against its white noise) */

/* 2^(j/8), j = 1..7 (bin edges within an octave) and 2^((s + 0.5)/8), s = 0..7 (bin centres). */
static const scalcal_real kEdge[7] = {(scalcal_real)1.0905077326652577, (scalcal_real)1.1892071150027210,
                                      (scalcal_real)1.2968395546510096, (scalcal_real)1.4142135623730951,
                                      (scalcal_real)1.5422108254079407, (scalcal_real)1.6817928305074290,
                                      (scalcal_real)1.8340080864093424};
static const scalcal_real kCentre[8] = {(scalcal_real)1.0442737824274138, (scalcal_real)1.1387886347566916,
                                        (scalcal_real)1.2418578120734840, (scalcal_real)1.3542555469368927,
                                        (scalcal_real)1.4768261459394993, (scalcal_real)1.6104903319492543,
                                        (scalcal_real)1.7562521603732995, (scalcal_real)1.9152065613971474};

void scalcal_detector_options_default(scalcal_detector_options* o, scalcal_real rate_hz) {
  memset(o, 0, sizeof *o);
  o->rate_hz = rate_hz;
  o->window_s = 1;
  o->threshold_factor = 6;
  o->min_still_s = 1;
  o->whiteness_min = (scalcal_real)0.25;
}

scalcal_status scalcal_detector_init(scalcal_detector* det, const scalcal_detector_options* o) {
  scalcal_real w, m;
  uint32_t window;
  if (!det || !o) return SCALCAL_E_ARGUMENT;
  if (!(o->rate_hz > 0 && o->rate_hz < (scalcal_real)1e7) || !(o->window_s > 0) || !(o->threshold_factor > 1) ||
      !(o->min_still_s >= 0) || !(o->whiteness_min >= 0) || !sc_finite(o->window_s) || !sc_finite(o->min_still_s))
    return SCALCAL_E_ARGUMENT;
  memset(det, 0, sizeof *det);
  det->options = *o;
  /* The host's window: window_s rate samples, at least 11, odd. */
  w = o->window_s * o->rate_hz;
  if (w < 11) w = 11;
  if (w > (scalcal_real)1e7) return SCALCAL_E_ARGUMENT;
  window = ((uint32_t)(w + (scalcal_real)0.5)) | 1u;
  det->block_samples = (window + SCALCAL_DETECTOR_BLOCKS / 2) / SCALCAL_DETECTOR_BLOCKS;
  if (det->block_samples < 1) det->block_samples = 1;
  m = o->min_still_s * o->rate_hz;
  if (m > (scalcal_real)4e9) return SCALCAL_E_ARGUMENT;
  det->min_samples = (uint32_t)m;
  if ((scalcal_real)det->min_samples < m) det->min_samples += 1;
  if (det->min_samples < 1) det->min_samples = 1;
  det->filling.valid = 1;
  return SCALCAL_OK;
}

/* floor(8 log2 v) for v > 0, exactly: v = g 2^E with g in [1, 2), and the edges 2^(j/8). */
static int32_t bin_of(scalcal_real v) {
  int e, s = 0;
  const scalcal_real g = 2 * sc_frexp(v, &e);
  while (s < 7 && g >= kEdge[s]) ++s;
  return (int32_t)(8 * (e - 1) + s);
}

static scalcal_real centre_of(int32_t bin) {
  const int32_t octave = bin >= 0 ? bin / 8 : -((-bin + 7) / 8);
  return sc_ldexp(kCentre[bin - 8 * octave], (int)octave);
}

/* The noise floor from the histogram: the median of the quiet windows, those within 3 times the
 * 5 % quantile (bins up to QUIET_BINS above its bin); each value taken at its bin's centre. */
static void update_floor(scalcal_detector* det) {
  uint32_t rank, seen = 0, quiet = 0;
  int k, k05 = 0, last;
  if (det->histogram_total < MIN_WINDOWS) return;
  rank = (det->histogram_total - 1) / 20; /* floor(0.05 (total - 1)), in integers */
  for (k = 0; k < SCALCAL_FLOOR_BINS; ++k) {
    seen += det->histogram[k];
    if (seen > rank) {
      k05 = k;
      break;
    }
  }
  last = k05 + QUIET_BINS < SCALCAL_FLOOR_BINS ? k05 + QUIET_BINS : SCALCAL_FLOOR_BINS - 1;
  for (k = 0; k <= last; ++k) quiet += det->histogram[k];
  rank = (quiet - 1) / 2;
  seen = 0;
  for (k = 0; k <= last; ++k) {
    seen += det->histogram[k];
    if (seen > rank) break;
  }
  det->floor = centre_of(det->histogram_base + k);
  det->threshold = det->options.threshold_factor * det->floor;
}

static void histogram_add(scalcal_detector* det, scalcal_real v) {
  int32_t index;
  int k;
  if (!det->has_base) {
    det->histogram_base = bin_of(v) - SCALCAL_FLOOR_BINS / 2;
    det->has_base = 1;
  }
  index = bin_of(v) - det->histogram_base;
  if (index < 0) index = 0;
  if (index >= SCALCAL_FLOOR_BINS) index = SCALCAL_FLOOR_BINS - 1;
  if (det->histogram_total >= 65535u) { /* forget half: the floor follows a slowly changing sensor */
    det->histogram_total = 0;
    for (k = 0; k < SCALCAL_FLOOR_BINS; ++k) det->histogram[k] >>= 1, det->histogram_total += det->histogram[k];
  }
  det->histogram[index] += 1;
  det->histogram_total += 1;
  update_floor(det);
}

static scalcal_event close_pose(scalcal_detector* det, scalcal_pose_set* set) {
  scalcal_event event = SCALCAL_EVENT_NONE;
  if (det->in_pose) {
    if (det->pose.count >= det->min_samples) {
      if (scalcal_pose_set_append(set, &det->pose) == SCALCAL_OK) {
        event = SCALCAL_EVENT_POSE;
        det->closed_first = det->pose.first;
        det->closed_last = det->pose.last;
      } else
        event = SCALCAL_EVENT_FULL, det->dropped += 1;
    } else {
      det->short_runs += 1;
    }
  }
  det->in_pose = 0;
  scalcal_pose_sum_clear(&det->pose);
  return event;
}

/* The run-length rules for the window's centre block: start, grow, restart or close the pose. */
static scalcal_event judge_block(scalcal_detector* det, scalcal_pose_set* set, const scalcal_block* centre, int still,
                                 scalcal_real v) {
  scalcal_event event = SCALCAL_EVENT_NONE;
  scalcal_pose_sum grown;
  if (!still) return close_pose(det, set);
  if (det->in_pose && det->pose_max >= det->threshold) { /* the floor fell below what the pose saw */
    det->restarts += 1;
    det->in_pose = 0;
  }
  if (det->in_pose) {
    grown = det->pose;
    scalcal_pose_sum_merge(&grown, &centre->stats);
    if (scalcal_pose_sum_variance_norm(&grown) < det->threshold && grown.count <= MAX_POSE_SAMPLES) {
      det->pose = grown;
      if (v > det->pose_max) det->pose_max = v;
      return SCALCAL_EVENT_NONE;
    }
    event = close_pose(det, set); /* the pose drifts (or is long enough): a new one from here */
  }
  det->pose = centre->stats;
  det->pose_max = v;
  det->in_pose = 1;
  return event;
}

/* A block is complete: the window of the last BLOCKS blocks judges its centre block. */
static scalcal_event window_done(scalcal_detector* det, scalcal_pose_set* set) {
  scalcal_pose_sum merged;
  scalcal_real diff2 = 0, v = 0, variance;
  uint32_t diffs = 0;
  int k, valid = 1, still;
  const scalcal_block* centre = &det->ring[(det->blocks - 1 - HALF) % SCALCAL_DETECTOR_BLOCKS];
  scalcal_pose_sum_clear(&merged);
  for (k = 0; k < SCALCAL_DETECTOR_BLOCKS; ++k) {
    const scalcal_block* b = &det->ring[k];
    valid = valid && b->valid;
    scalcal_pose_sum_merge(&merged, &b->stats);
    diff2 += b->diff2;
    diffs += b->diffs;
  }
  if (valid) {
    v = scalcal_pose_sum_variance_norm(&merged);
    variance = (merged.scatter[0] + merged.scatter[1] + merged.scatter[2]) / (scalcal_real)merged.count;
    /* white noise: E |x_k - x_(k-1)|^2 = 2 variance; smooth motion: far less */
    if (v > 0 && diffs > 0 && sc_finite(v) && diff2 / (scalcal_real)diffs >= 2 * det->options.whiteness_min * variance)
      histogram_add(det, v);
  }
  if (valid && det->floor > 0) { /* the stream's moving share (the host's `motion`, README.md) */
    set->windows_judged += 1;
    if (!(v <= MOVING_FACTOR * det->floor)) set->windows_moving += 1;
  }
  still = valid && det->floor > 0 && v < det->threshold && sc_finite(v);
  return judge_block(det, set, centre, still, v);
}

static int saturated(const scalcal_detector_options* o, const scalcal_real x[3]) {
  int k;
  if (!(o->adc_min < o->adc_max)) return 0;
  for (k = 0; k < 3; ++k)
    if (x[k] <= o->adc_min || x[k] >= o->adc_max) return 1;
  return 0;
}

scalcal_event scalcal_detector_push(scalcal_detector* det, scalcal_pose_set* set, const scalcal_real x[3]) {
  scalcal_event event = SCALCAL_EVENT_NONE, judged = SCALCAL_EVENT_NONE;
  scalcal_block* b = &det->filling;
  int k;
  if (!sc_finite(x[0]) || !sc_finite(x[1]) || !sc_finite(x[2]) || saturated(&det->options, x)) {
    b->valid = 0;
    det->has_last = 0;
    det->invalid += 1;
    event = SCALCAL_EVENT_INVALID;
  } else {
    if (det->has_last)
      for (k = 0; k < 3; ++k) b->diff2 += (x[k] - det->last[k]) * (x[k] - det->last[k]);
    b->diffs += det->has_last ? 1u : 0u;
    for (k = 0; k < 3; ++k) det->last[k] = x[k];
    det->has_last = 1;
    scalcal_pose_sum_add(set, &b->stats, x, det->index);
  }
  det->index += 1;
  b->pushed += 1;
  if (b->pushed == det->block_samples) {
    det->ring[det->blocks % SCALCAL_DETECTOR_BLOCKS] = *b;
    det->blocks += 1;
    memset(b, 0, sizeof *b);
    b->valid = 1;
    if (det->blocks >= SCALCAL_DETECTOR_BLOCKS) judged = window_done(det, set);
  }
  return judged != SCALCAL_EVENT_NONE ? judged : event;
}

scalcal_event scalcal_detector_finish(scalcal_detector* det, scalcal_pose_set* set) { return close_pose(det, set); }

scalcal_stream_state scalcal_detector_state(const scalcal_detector* det) {
  if (!(det->floor > 0)) return SCALCAL_STREAM_NO_FLOOR;
  return det->in_pose ? SCALCAL_STREAM_STILL : SCALCAL_STREAM_MOVING;
}

const char* scalcal_detector_state_text(const scalcal_detector* det) {
  switch (scalcal_detector_state(det)) {
    case SCALCAL_STREAM_NO_FLOOR:
      return "no noise floor yet (no quiet window: the stream has not paused)";
    case SCALCAL_STREAM_MOVING:
      return "moving";
    case SCALCAL_STREAM_STILL:
      return "still";
  }
  return "unknown";
}
