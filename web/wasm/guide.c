/* web/wasm/guide.c: the page's Guide (issue 55 item 2): embedded/'s streaming still-pose detector, fit and
 * guidance (scalcal/detector.h, fit.h, guidance.h), unchanged, behind five C functions the page calls with
 * chunks of samples. One guide at a time (static state, as on a board); numbers go back in a static array of
 * doubles (the layout is GUIDE_* below, read by web/app.js). */
#include <math.h>
#include <string.h>

#include "scalcal/detector.h"
#include "scalcal/fit.h"
#include "scalcal/guidance.h"

/* The report's layout (doubles): fixed fields, then each pose's direction (x, y, z). */
enum {
  GUIDE_POSES = 0,  /* poses stored */
  GUIDE_STATE,      /* scalcal_stream_state */
  GUIDE_SAMPLES,    /* samples pushed */
  GUIDE_FIT_STATUS, /* scalcal_fit's status (0: the directions and guidance are the fit's) */
  GUIDE_MODEL,      /* the model fitted (9 when judged on the nominal calibration) */
  GUIDE_EFFICIENCY, /* 4: D, A, E, S against the sphere's limit (NaN: not identifiable yet) */
  GUIDE_NEXT = 9,   /* the next pose's index in scalcal_candidates26 (-1: none) */
  GUIDE_NEXT_DIR,   /* 3: its direction */
  GUIDE_AFTER = 13, /* the criterion once it is added */
  GUIDE_FLOOR,      /* the detector's noise floor (0: none yet) */
  GUIDE_QUALITY,    /* scalcal_program_quality_of's status */
  GUIDE_FIXED = 16
};

static scalcal_detector det;
static scalcal_pose storage[SCALCAL_MAX_POSES];
static scalcal_pose_set set;
static scalcal_fit_options fit_options;
static double report[GUIDE_FIXED + 3 * SCALCAL_MAX_POSES];

/* A new stream of rate_hz samples per second; magnitude <= 0: the field's strength is unknown. 0 on success. */
int scalcal_guide_start(double rate_hz, double magnitude) {
  scalcal_detector_options o;
  scalcal_detector_options_default(&o, (scalcal_real)rate_hz);
  scalcal_fit_options_default(&fit_options);
  if (magnitude > 0)
    fit_options.magnitude = (scalcal_real)magnitude;
  else
    fit_options.magnitude_auto = 1;
  if (scalcal_pose_set_init(&set, storage, SCALCAL_MAX_POSES) != SCALCAL_OK) return 1;
  return scalcal_detector_init(&det, &o) == SCALCAL_OK ? 0 : 1;
}

/* count samples (x, y, z interleaved, raw units); returns the poses stored so far. */
int scalcal_guide_push(const double* xyz, int count) {
  int k;
  for (k = 0; k < count; ++k) {
    scalcal_real x[3];
    x[0] = (scalcal_real)xyz[3 * k], x[1] = (scalcal_real)xyz[3 * k + 1], x[2] = (scalcal_real)xyz[3 * k + 2];
    scalcal_detector_push(&det, &set, x);
  }
  return (int)set.count;
}

/* The end of the stream (a pose being summed is closed); returns the poses stored. */
int scalcal_guide_finish(void) {
  scalcal_detector_finish(&det, &set);
  return (int)set.count;
}

/* Before a fit converges: the poses judged through a nominal calibration, the offset at the middle of the
 * pose means' range and a unit matrix (directions only need the offset roughly right). */
static scalcal_status nominal(scalcal_calibration* cal) {
  static const scalcal_real unit[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  scalcal_real lo[3], hi[3], m[3], offset[3];
  uint32_t i, a;
  if (set.count == 0) return SCALCAL_E_TOO_FEW_POSES;
  for (i = 0; i < set.count; ++i) {
    scalcal_pose_mean(&set, i, m);
    for (a = 0; a < 3; ++a) {
      if (i == 0 || m[a] < lo[a]) lo[a] = m[a];
      if (i == 0 || m[a] > hi[a]) hi[a] = m[a];
    }
  }
  for (a = 0; a < 3; ++a) offset[a] = (lo[a] + hi[a]) / 2;
  return scalcal_calibration_from_matrix(cal, SCALCAL_MODEL_PAPER9, offset, unit, 1, 1, 1);
}

/* The poses so far: fitted (fit_options as started) when the fit succeeds, else through the nominal
 * calibration; the program's efficiency and the next pose by `criterion` (scalcal_criterion) among the 26
 * directions of a cube. Returns the report (GUIDE_* above). */
double* scalcal_guide_report(int criterion) {
  static scalcal_calibration cal;
  static scalcal_fit_report fit;
  scalcal_program_quality q;
  scalcal_model model = SCALCAL_MODEL_PAPER9;
  scalcal_status s;
  scalcal_real after = NAN, eta[3];
  uint32_t best = 0, i;
  int k;
  for (k = 0; k < GUIDE_FIXED; ++k) report[k] = NAN;
  report[GUIDE_POSES] = set.count;
  report[GUIDE_STATE] = (double)scalcal_detector_state(&det);
  report[GUIDE_SAMPLES] = det.index;
  report[GUIDE_FLOOR] = (double)det.floor;
  report[GUIDE_NEXT] = -1;
  s = set.count ? scalcal_fit(&set, &fit_options, &cal, &fit) : SCALCAL_E_TOO_FEW_POSES;
  report[GUIDE_FIT_STATUS] = (double)s;
  if (s == SCALCAL_OK)
    model = fit.model;
  else if (nominal(&cal) != SCALCAL_OK)
    return report;
  report[GUIDE_MODEL] = (double)model;
  s = scalcal_program_quality_of(&set, &cal, model, &q);
  report[GUIDE_QUALITY] = (double)s;
  if (s == SCALCAL_OK && q.full_rank)
    for (k = 0; k < 4; ++k) report[GUIDE_EFFICIENCY + k] = (double)q.efficiency[k];
  if (scalcal_next_pose(&set, &cal, model, (scalcal_criterion)criterion, scalcal_candidates26, 26, &best, &after) ==
      SCALCAL_OK) {
    report[GUIDE_NEXT] = best;
    for (k = 0; k < 3; ++k) report[GUIDE_NEXT_DIR + k] = (double)scalcal_candidates26[best][k];
    report[GUIDE_AFTER] = (double)after;
  }
  for (i = 0; i < set.count; ++i) {
    scalcal_pose_direction(&set, i, &cal, eta);
    for (k = 0; k < 3; ++k) report[GUIDE_FIXED + 3 * i + (uint32_t)k] = (double)eta[k];
  }
  return report;
}
