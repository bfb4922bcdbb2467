/* The program's quality against the sphere's limits and the next pose (scalcal/guidance.h). */
#include <string.h>

#include "internal.h"
#include "scalcal/guidance.h"

#define R3 0.57735026918962576451 /* 1/sqrt(3) */
#define R2 0.70710678118654752440 /* 1/sqrt(2) */
const scalcal_real scalcal_candidates26[26][3] = {
    {1, 0, 0},      {-1, 0, 0},    {0, 1, 0},      {0, -1, 0},     {0, 0, 1},      {0, 0, -1},    {R2, R2, 0},
    {R2, -R2, 0},   {-R2, R2, 0},  {-R2, -R2, 0},  {0, R2, R2},    {0, R2, -R2},   {0, -R2, R2},  {0, -R2, -R2},
    {R2, 0, R2},    {-R2, 0, R2},  {R2, 0, -R2},   {-R2, 0, -R2},  {R3, R3, R3},   {R3, R3, -R3}, {R3, -R3, R3},
    {R3, -R3, -R3}, {-R3, R3, R3}, {-R3, R3, -R3}, {-R3, -R3, R3}, {-R3, -R3, -R3}};

/* The sphere's limits by model (scalcal limits --model NAME). */
static void limits_of(int p, scalcal_real limit[4]) {
  if (p == 9) {
    limit[0] = (scalcal_real)15377343.75;        /* 61509375/4 (proofs/d_limit.md) */
    limit[1] = (scalcal_real)70.455844122715710; /* 45 + 18 sqrt 2 (proofs/aes_limits.md) */
    limit[2] = 12;
    limit[3] = (scalcal_real)11.196152422706632; /* 6 + 3 sqrt 3 */
  } else if (p == 6) {
    limit[0] = 729, limit[1] = 18, limit[2] = 3, limit[3] = 3; /* proofs/axis6_limits.md */
  } else {
    limit[0] = 27, limit[1] = 9, limit[2] = 3, limit[3] = 3; /* proofs/bias3_limits.md */
  }
}

void scalcal_pose_direction(const scalcal_pose_set* set, uint32_t i, const scalcal_calibration* cal,
                            scalcal_real eta[3]) {
  scalcal_real m[3], norm;
  scalcal_pose_mean(set, i, m);
  scalcal_correct(cal, m, eta);
  norm = sc_norm3(eta);
  eta[0] /= norm, eta[1] /= norm, eta[2] /= norm;
}

static void information_of(const scalcal_pose_set* set, const scalcal_calibration* cal, int p, scalcal_real* info) {
  scalcal_real e[3], h[SC_P];
  uint32_t i;
  int r, s;
  memset(info, 0, sizeof(scalcal_real) * (unsigned)(p * p));
  for (i = 0; i < set->count; ++i) {
    scalcal_pose_direction(set, i, cal, e);
    sc_row(e, h);
    for (r = 0; r < p; ++r)
      for (s = 0; s < p; ++s) info[r * p + s] += h[r] * h[s];
  }
}

/* The four criteria of K (inverse information, p x p) for n positions. */
static void criteria_of(int p, const scalcal_real* K, scalcal_real n, scalcal_real value[4]) {
  scalcal_real values[SC_P], trace = 0, diag = 0, det = 1, np = 1;
  int r;
  sc_eigen_symmetric(p, K, values, 0);
  for (r = 0; r < p; ++r) {
    trace += K[r * p + r];
    if (K[r * p + r] > diag) diag = K[r * p + r];
    det *= values[r];
    np *= n;
  }
  value[0] = np * det;
  value[1] = n * trace;
  value[2] = n * values[p - 1];
  value[3] = n * diag;
}

static int model_parameters(scalcal_model model) {
  return model == SCALCAL_MODEL_BIAS3 ? 3 : model == SCALCAL_MODEL_AXIS6 ? 6 : model == SCALCAL_MODEL_PAPER9 ? 9 : 0;
}

scalcal_status scalcal_program_quality_of(const scalcal_pose_set* set, const scalcal_calibration* cal,
                                          scalcal_model model, scalcal_program_quality* out) {
  const int p = model_parameters(model);
  scalcal_real K[SC_P * SC_P], values[SC_P];
  int c;
  if (!set || !cal || !out || p == 0) return SCALCAL_E_ARGUMENT;
  memset(out, 0, sizeof *out);
  out->positions = set->count;
  limits_of(p, out->limit);
  for (c = 0; c < 4; ++c) out->value[c] = out->efficiency[c] = (scalcal_real)NAN;
  out->condition = (scalcal_real)INFINITY;
  if (set->count == 0) return SCALCAL_OK;
  information_of(set, cal, p, K);
  sc_eigen_symmetric(p, K, values, 0);
  if (!(values[0] >
        (scalcal_real)(set->count > (uint32_t)p ? set->count : (uint32_t)p) * SCALCAL_EPSILON * values[p - 1]))
    return SCALCAL_OK;
  if (!sc_spd_inverse(p, K, K)) return SCALCAL_OK;
  out->full_rank = 1;
  out->condition = values[p - 1] / values[0];
  criteria_of(p, K, (scalcal_real)set->count, out->value);
  for (c = 0; c < 4; ++c) out->efficiency[c] = out->limit[c] / out->value[c];
  out->efficiency[0] = sc_root(out->efficiency[0], p);
  return SCALCAL_OK;
}

/* K' = K - K h h^T K / (1 + h^T K h): the inverse information with one more position. */
static scalcal_real add_position(int p, const scalcal_real* K, const scalcal_real* h, scalcal_real* Kn) {
  scalcal_real Kh[SC_P], d = 1;
  int r, s;
  for (r = 0; r < p; ++r) {
    Kh[r] = 0;
    for (s = 0; s < p; ++s) Kh[r] += K[r * p + s] * h[s];
    d += h[r] * Kh[r];
  }
  for (r = 0; r < p; ++r)
    for (s = 0; s < p; ++s) Kn[r * p + s] = K[r * p + s] - Kh[r] * Kh[s] / d;
  return d;
}

scalcal_status scalcal_next_pose(const scalcal_pose_set* set, const scalcal_calibration* cal, scalcal_model model,
                                 scalcal_criterion criterion, const scalcal_real (*candidates)[3], uint32_t count,
                                 uint32_t* best, scalcal_real* value_after) {
  const int p = model_parameters(model);
  scalcal_real K[SC_P * SC_P], Kn[SC_P * SC_P], h[SC_P], values[SC_P], best_score = 0;
  uint32_t j;
  int r, full;
  if (!set || !cal || !candidates || !best || count == 0 || p == 0 || (unsigned)criterion > 3u)
    return SCALCAL_E_ARGUMENT;
  information_of(set, cal, p, K);
  sc_eigen_symmetric(p, K, values, 0);
  full = set->count > 0 && values[0] > (scalcal_real)(set->count > (uint32_t)p ? set->count : (uint32_t)p) *
                                           SCALCAL_EPSILON * values[p - 1];
  if (!full) /* regularised: the candidate richest in what the program lacks */
    for (r = 0; r < p; ++r) K[r * p + r] += (scalcal_real)1e-6 * (scalcal_real)(set->count > 0 ? set->count : 1);
  if (!sc_spd_inverse(p, K, K)) return SCALCAL_E_NOT_FINITE;
  *best = 0;
  for (j = 0; j < count; ++j) {
    scalcal_real score, value[4];
    sc_row(candidates[j], h);
    if (full) {
      const scalcal_real d = add_position(p, K, h, Kn);
      criteria_of(p, Kn, (scalcal_real)(set->count + 1), value);
      (void)d;
      score = -value[criterion];
    } else {
      score = add_position(p, K, h, Kn);
    }
    if (j == 0 || score > best_score) best_score = score, *best = j;
  }
  if (value_after) *value_after = full ? -best_score : (scalcal_real)NAN;
  return SCALCAL_OK;
}
