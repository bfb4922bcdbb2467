/* Streaming still-pose detection: samples go in one at a time, still poses come out as per-pose sums
 * in a pose set. A small explicit state machine (README.md, "The still-pose detector", states every
 * rule): samples are summed in blocks; a moving window of SCALCAL_DETECTOR_BLOCKS blocks gives a
 * variance norm (the norm over the three axes of each axis' variance) and a whiteness (the mean
 * squared successive difference over twice the variance: 1 for white noise, near 0 for motion);
 * white windows feed a log-scale histogram whose quiet part gives the noise floor online; the
 * window's centre block is still while the window's variance norm stays below threshold_factor
 * times that floor; runs of still blocks of at least min_still_s are poses. No sample is stored. */
#ifndef SCALCAL_DETECTOR_H
#define SCALCAL_DETECTOR_H

#include <stdint.h>

#include "scalcal/pose.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Blocks per window (odd): the window slides by one block; a block's stillness is known when the
 * window centred on it is complete, (BLOCKS - 1) / 2 blocks later. */
#ifndef SCALCAL_DETECTOR_BLOCKS
#define SCALCAL_DETECTOR_BLOCKS 5
#endif
/* The noise floor's histogram: 8 bins per octave over 64 octaves around the first white window. */
#define SCALCAL_FLOOR_BINS 512
#define SCALCAL_FLOOR_BINS_PER_OCTAVE 8

typedef struct {
  scalcal_real rate_hz;          /* samples per second (> 0) */
  scalcal_real window_s;         /* 1: the window (at least 11 samples, odd, as the host's) */
  scalcal_real threshold_factor; /* 6: still below this times the noise floor */
  scalcal_real min_still_s;      /* 1: shorter still runs are not poses */
  scalcal_real whiteness_min;    /* 0.25: less white windows (motion) never set the noise floor */
  scalcal_real adc_min, adc_max; /* a sample with a component <= adc_min or >= adc_max is saturated
                                    (unused when adc_min >= adc_max, the default) */
} scalcal_detector_options;

/* Where the stream is: no noise floor yet (fewer than 2 x SCALCAL_DETECTOR_BLOCKS white windows: a
 * stream that never pauses stays here), moving, or still (a pose is being summed). */
typedef enum { SCALCAL_STREAM_NO_FLOOR = 0, SCALCAL_STREAM_MOVING, SCALCAL_STREAM_STILL } scalcal_stream_state;

/* What one pushed sample caused. */
typedef enum {
  SCALCAL_EVENT_NONE = 0,
  SCALCAL_EVENT_POSE,   /* a pose closed and was stored (set->count grew) */
  SCALCAL_EVENT_FULL,   /* a pose closed but the set is full: it was dropped */
  SCALCAL_EVENT_INVALID /* the sample is not finite or saturated: not used, and it breaks stillness */
} scalcal_event;

typedef struct {
  scalcal_pose_sum stats;
  scalcal_real diff2; /* sum over the block of |x_k - x_(k-1)|^2 (all three axes) */
  uint32_t diffs;
  uint32_t pushed; /* samples pushed into the block, valid or not */
  int valid;       /* every sample pushed was finite and not saturated */
} scalcal_block;

/* The detector's whole state: about 1.5 KB in float with 5 blocks. Read the fields; change them only
 * through the functions. */
typedef struct {
  scalcal_detector_options options;
  uint32_t block_samples; /* samples per block: round(window / BLOCKS), at least 1 */
  uint32_t min_samples;   /* ceil(min_still_s rate) */
  uint32_t index;         /* samples pushed so far */
  scalcal_block filling;
  scalcal_block ring[SCALCAL_DETECTOR_BLOCKS];
  uint32_t blocks; /* completed blocks */
  scalcal_real last[3];
  int has_last;
  uint16_t histogram[SCALCAL_FLOOR_BINS];
  uint32_t histogram_total;
  int32_t histogram_base; /* the bin number of index 0 */
  int has_base;
  scalcal_real floor;     /* the noise floor (a still window's variance norm, units squared); 0: none yet */
  scalcal_real threshold; /* threshold_factor x floor */
  scalcal_pose_sum pose;  /* the pose being summed */
  scalcal_real pose_max;  /* the largest window variance norm of its blocks */
  int in_pose;
  uint32_t closed_first, closed_last; /* the stream indices of the last pose stored */
  uint32_t invalid, short_runs, dropped, restarts;
} scalcal_detector;

/* The defaults above for a stream of rate_hz samples per second. */
void scalcal_detector_options_default(scalcal_detector_options* options, scalcal_real rate_hz);

/* SCALCAL_E_ARGUMENT for a null pointer or an option out of range. */
scalcal_status scalcal_detector_init(scalcal_detector* det, const scalcal_detector_options* options);

/* One sample (raw units). Poses go to `set` (its origin is set by the first valid sample). */
scalcal_event scalcal_detector_push(scalcal_detector* det, scalcal_pose_set* set, const scalcal_real sample[3]);

/* The end of the stream: a pose being summed is closed (stored if long enough). The blocks whose
 * window is incomplete are not still, as the host leaves the log's last half window. */
scalcal_event scalcal_detector_finish(scalcal_detector* det, scalcal_pose_set* set);

scalcal_stream_state scalcal_detector_state(const scalcal_detector* det);
const char* scalcal_detector_state_text(const scalcal_detector* det);

#ifdef __cplusplus
}
#endif

#endif
