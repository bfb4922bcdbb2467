/* Tumbling mode: a magnetometer turned continuously, every sample a position (as `scalcal calibrate`
 * fits a tumbling log, docs/magnetometer.md), in constant memory. A device cannot keep 20000 samples,
 * and the fit's residual |A (x - o)| is not linear in the samples, so no fixed set of sums is exactly
 * sufficient for it. What is kept instead: the samples clustered as they come into at most
 * `capacity` cells of the caller's pose set (count, mean, scatter matrix per cell: a cell is a
 * pose), cells merged two by two by Ward's rule (the pair whose merging adds least scatter,
 * distances in units of each axis's noise) when a sample lies farther from every cell than the
 * cheapest pair. No sample is dropped: every valid sample is in exactly one cell. The fit
 * (scalcal_fit with options.tumble set) weights a cell by its samples and takes its samples' mean
 * modulus from their mean square, which is exact from the sums however far the cell spreads
 * (|c|^2 + tr(A S A^T) / n), less the radial noise's share (src/cell_modulus.c): the per-sample fit's
 * residuals, summed over the cell, up to terms of fourth order in the noise. What a cell loses is
 * how its samples' rows vary inside it (README.md "Tumbling mode": 0.4-0.9 of the library's
 * standard errors from the CLI's per-sample fit at 64 cells). One sample's noise comes from second
 * differences, as the host's. Not done here (README.md): the host's disturbed stretches (its
 * residuals need every sample after the fit; scalcal_tumble_gate gives further passes instead) and
 * its Newey-West widening for residuals correlated in time (the device's residual-based errors come
 * from the scatter between cells: batch means over directions). */
#ifndef SCALCAL_TUMBLE_H
#define SCALCAL_TUMBLE_H

#include <stdint.h>

#include "scalcal/calibration.h"
#include "scalcal/pose.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct scalcal_tumble {
  /* Settings (scalcal_tumble_init). */
  scalcal_real adc_min, adc_max; /* a component at or beyond either is saturated (off when min >= max) */
  /* The gate of a second pass (scalcal_tumble_gate): 0 when off. */
  const scalcal_calibration* gate;
  scalcal_real gate_limit; /* |corrected modulus / magnitude - 1| beyond this is disturbed */
  /* Second differences x_k - 2 x_(k-1) + x_(k-2) over runs of valid samples: per-axis mean square
   * (the samples relative to the set's first one) and their number. */
  scalcal_real previous[2][3];
  uint32_t run; /* valid samples in a row so far (saturated at 2) */
  scalcal_real d2[3];
  uint32_t nd;
  /* The cheapest pair of cells (Ward's cost n_a n_b / (n_a + n_b) |m_a - m_b|^2, each axis in units
   * of its noise so far) once the set is full. */
  uint32_t pair_a, pair_b;
  scalcal_real pair_cost;
  /* Counts. */
  uint32_t samples;   /* valid samples in cells */
  uint32_t invalid;   /* not finite or saturated */
  uint32_t disturbed; /* left out by the gate */
  uint32_t merges;    /* pairs of cells merged */
} scalcal_tumble;

/* Starts an empty accumulation into `cells` (emptied; its capacity is the maximum number of cells,
 * at least 9 for paper9). adc_min < adc_max to reject saturated samples, else no rail. */
scalcal_status scalcal_tumble_init(scalcal_tumble* t, scalcal_pose_set* cells, scalcal_real adc_min,
                                   scalcal_real adc_max);

/* A second pass: samples whose modulus under `cal` is off its magnitude by more than `limit`
 * (relative; for the host's 5 robust scales, 5 cal->noise / cal->magnitude: the noise comes from
 * second differences, which a slow disturbance hardly enters, where the residuals grow with it) are
 * counted as disturbed and not accumulated. cal must outlive the accumulation; null turns it off. */
void scalcal_tumble_gate(scalcal_tumble* t, const scalcal_calibration* cal, scalcal_real limit);

/* One raw sample: 1 when it went into a cell, 0 when it was invalid or gated out. */
int scalcal_tumble_push(scalcal_tumble* t, scalcal_pose_set* cells, const scalcal_real sample[3]);

/* One sample's noise per axis in raw units, from the second differences: sqrt(mean square / 6)
 * (white noise of variance s^2 gives second differences of variance 6 s^2); 0 before any. */
void scalcal_tumble_noise(const scalcal_tumble* t, scalcal_real noise[3]);

#ifdef __cplusplus
}
#endif

#endif
