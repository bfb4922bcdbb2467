/* Guidance while poses are collected: how good the program of poses measured so far is against the
 * sphere's proven limit of each criterion (`scalcal limits`; proofs/d_limit.md, aes_limits.md,
 * axis6_limits.md, bias3_limits.md), and which pose to ask for next: the candidate direction that
 * improves the chosen criterion most. A direction is where the measured vector (gravity's reaction,
 * the field) points in the sensor's frame: "turn me so that my +z points up" is (0, 0, 1). */
#ifndef SCALCAL_GUIDANCE_H
#define SCALCAL_GUIDANCE_H

#include "scalcal/calibration.h"
#include "scalcal/pose.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum {
  SCALCAL_CRITERION_D = 0,
  SCALCAL_CRITERION_A,
  SCALCAL_CRITERION_E,
  SCALCAL_CRITERION_S
} scalcal_criterion;

/* The program measured, as `scalcal evaluate --model` judges it: K = (H^T H)^-1 at the poses'
 * directions, D = N^P det K, A = N trace K, E = N lambda_max(K), S = N max_r K(r, r). */
typedef struct {
  uint32_t positions;
  int full_rank;          /* 0: K does not exist (values, efficiencies NaN) */
  scalcal_real condition; /* of H^T H */
  scalcal_real value[4];  /* by scalcal_criterion */
  scalcal_real limit[4];  /* the sphere's limit for the model (paper9: 61509375/4, 45 + 18 sqrt 2, 12, 6 + 3 sqrt 3) */
  scalcal_real efficiency[4]; /* limit / value; D's P-th root of it (1: as good as any program can be) */
} scalcal_program_quality;

/* The 26 directions of a cube's faces, edges and corners (normalised): what a hand or a box can
 * reach without a fixture. */
extern const scalcal_real scalcal_candidates26[26][3];

/* Pose i's direction as the calibration sees it: matrix (mean - offset), normalised. */
void scalcal_pose_direction(const scalcal_pose_set* set, uint32_t i, const scalcal_calibration* cal,
                            scalcal_real eta[3]);

/* The program of the set's poses under `model` (3, 6 or 9 parameters) through `cal` (the fit's, or a
 * nominal one from scalcal_calibration_from_matrix before any fit). */
scalcal_status scalcal_program_quality_of(const scalcal_pose_set* set, const scalcal_calibration* cal,
                                          scalcal_model model, scalcal_program_quality* out);

/* The best next pose among `count` candidate directions (unit vectors): the one that minimises
 * `criterion` of the program with it added (the program is then N + 1 poses). While the program
 * cannot yet identify the model, the candidate that adds most information (the largest
 * h^T (H^T H + delta I)^-1 h, delta = 1e-6 N) is chosen whatever the criterion. *best is its index;
 * *value_after (may be null) the criterion after adding it (NaN while not identifiable). */
scalcal_status scalcal_next_pose(const scalcal_pose_set* set, const scalcal_calibration* cal, scalcal_model model,
                                 scalcal_criterion criterion, const scalcal_real (*candidates)[3], uint32_t count,
                                 uint32_t* best, scalcal_real* value_after);

#ifdef __cplusplus
}
#endif

#endif
