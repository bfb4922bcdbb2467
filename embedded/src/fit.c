/* scalcal_fit (scalcal/fit.h): the model the layout carries, the start, the estimator, the composed
 * correction and its errors, in the order `scalcal calibrate` takes them; every refusal of the
 * host is a status here. */
#include <string.h>

#include "fit_internal.h"
#include "scalcal/tumble.h"

void scalcal_fit_options_default(scalcal_fit_options* o) {
  memset(o, 0, sizeof *o);
  o->model = SCALCAL_MODEL_AUTO;
  o->magnitude = 1;
  o->max_iterations = 50;
}

static int poses_finite(const scalcal_pose_set* set) {
  uint32_t i;
  int k;
  for (i = 0; i < set->count; ++i) {
    const scalcal_pose* p = &set->poses[i];
    if (p->count == 0) return 0;
    for (k = 0; k < 3; ++k)
      if (!sc_finite(p->mean[k]) || !sc_finite(set->origin[k])) return 0;
    for (k = 0; k < 6; ++k)
      if (!sc_finite(p->scatter[k])) return 0;
  }
  return 1;
}

/* The model (the host's layout_directions, choose_model and judge_layout): the directions of the
 * means as they are when in the field's units, else through an axis-aligned ellipsoid. */
static scalcal_status choose(const sc_problem* q0, scalcal_model asked, int magnitude_auto, scalcal_fit_report* r) {
  static const int kModels[3] = {9, 6, 3};
  sc_correction axis;
  const sc_correction* through = 0;
  const uint32_t n = q0->set->count;
  scalcal_real ratio;
  int k;
  if (n < (asked == SCALCAL_MODEL_AUTO ? 3u : (uint32_t)asked)) return SCALCAL_E_TOO_FEW_POSES;
  ratio = sc_median_ratio(q0);
  if (magnitude_auto || !(SC_FABS(ratio - 1) <= SC_IN_UNITS)) {
    if (!sc_fit_ellipsoid(q0, 1, SC_SHAPE_AXIS_ALIGNED, &axis)) return SCALCAL_E_NO_START;
    through = &axis;
  }
  for (k = 0; k < 3; ++k) {
    const int p = kModels[k];
    if (asked != SCALCAL_MODEL_AUTO && p != (int)asked) continue;
    r->model = (scalcal_model)p;
    r->condition = n >= (uint32_t)p ? sc_layout_condition(q0, p, through) : (scalcal_real)INFINITY;
    if (r->condition <= SC_CARRY_CONDITION) return SCALCAL_OK;
  }
  return SCALCAL_E_NOT_IDENTIFIABLE;
}

/* The correction of the estimate composed with the start, in the paper's convention. */
static scalcal_status compose(const sc_problem* q, const scalcal_real* X, scalcal_calibration* cal) {
  sc_meter m;
  sc_correction out;
  int k;
  sc_meter_of(q, X, &m);
  if (!m.valid) return SCALCAL_E_DEGENERATE;
  cal->nominal_gain = 1;
  if (!q->started) {
    memcpy(out.offset, m.bias, sizeof out.offset);
    memcpy(out.matrix, m.Ginv, sizeof out.matrix);
    memcpy(out.scale, m.gain, sizeof out.scale);
    for (k = 0; k < 3; ++k) out.nonorthogonality[k] = q->p >= 9 ? X[6 + k] : 0;
  } else {
    /* physical = G^-1 (y - Delta), y = T (raw - o): matrix G^-1 T, offset o + T^-1 Delta. */
    scalcal_real GT[9], Ti[9], d[3], offset[3];
    sc_mul3(m.Ginv, q->start.matrix, GT);
    if (sc_inverse3(q->start.matrix, Ti) == 0) return SCALCAL_E_DEGENERATE;
    sc_mul3v(Ti, m.bias, d);
    for (k = 0; k < 3; ++k) offset[k] = q->start.offset[k] + d[k];
    if (!sc_canonical(GT, offset, &out)) return SCALCAL_E_DEGENERATE;
    for (k = 0; k < 3; ++k) out.offset[k] += q->set->origin[k];
    cal->nominal_gain = sc_root(out.scale[0] * out.scale[1] * out.scale[2], 3);
  }
  memcpy(cal->offset, out.offset, sizeof cal->offset);
  memcpy(cal->matrix, out.matrix, sizeof cal->matrix);
  for (k = 0; k < 3; ++k) {
    cal->gain[k] = out.scale[k];
    cal->scale_deviation[k] = out.scale[k] / cal->nominal_gain - 1;
    cal->nonorthogonality[k] = out.nonorthogonality[k];
  }
  return SCALCAL_OK;
}

/* What `scalcal correct` refuses: a matrix whose condition number (2-norm) exceeds 100. */
static int matrix_usable(const scalcal_calibration* cal) {
  scalcal_real MtM[9], values[3];
  const scalcal_real* a = &cal->matrix[0][0];
  int i, j;
  for (i = 0; i < 3; ++i)
    for (j = 0; j < 3; ++j) MtM[i * 3 + j] = a[i] * a[j] + a[3 + i] * a[3 + j] + a[6 + i] * a[6 + j];
  sc_eigen_symmetric(3, MtM, values, 0);
  return values[0] > 0 && values[2] <= SC_MATRIX_CONDITION * SC_MATRIX_CONDITION * values[0];
}

static int calibration_finite(const scalcal_calibration* cal) {
  int k;
  for (k = 0; k < 3; ++k)
    if (!sc_finite(cal->offset[k]) || !sc_finite(cal->gain[k]) || !sc_finite(cal->nonorthogonality[k]) ||
        !sc_finite(cal->matrix[k][0]) || !sc_finite(cal->matrix[k][1]) || !sc_finite(cal->matrix[k][2]))
      return 0;
  return sc_finite(cal->residual_rms) && sc_finite(cal->nominal_gain);
}

/* The start and the layout at the started means (the host's started_data and check_layout). */
static scalcal_status start_and_check(sc_problem* q, int magnitude_auto) {
  const sc_shape shape = q->p == 9 ? SC_SHAPE_GENERAL : q->p == 6 ? SC_SHAPE_AXIS_ALIGNED : SC_SHAPE_SPHERE;
  const scalcal_real ratio = sc_median_ratio(q);
  scalcal_real condition;
  q->started = magnitude_auto || SC_FABS(ratio - 1) > SC_IN_UNITS || !sc_finite(ratio);
  if (q->started) {
    if (!sc_fit_ellipsoid(q, q->magnitude, shape, &q->start)) {
      q->started = 0;
      return SCALCAL_E_NO_START;
    }
  }
  {
    const scalcal_real r = sc_median_ratio(q);
    if (!(r >= (scalcal_real)0.5 && r <= 2)) return SCALCAL_E_MAGNITUDE;
  }
  condition = sc_layout_condition(q, q->p, 0);
  if (!(condition <= SC_ILL_CONDITIONED)) return SCALCAL_E_NOT_IDENTIFIABLE;
  return SCALCAL_OK;
}

scalcal_status scalcal_fit(const scalcal_pose_set* set, const scalcal_fit_options* options, scalcal_calibration* cal,
                           scalcal_fit_report* report) {
  scalcal_fit_report local;
  scalcal_calibration out;
  sc_problem q;
  scalcal_real X[SC_P];
  scalcal_status status;
  scalcal_fit_report* r = report ? report : &local;
  const int magnitude_auto = options && options->magnitude_auto;
  memset(r, 0, sizeof *r);
  if (!set || !options || !cal || !set->poses) return SCALCAL_E_ARGUMENT;
  if (options->model != SCALCAL_MODEL_AUTO && options->model != SCALCAL_MODEL_BIAS3 &&
      options->model != SCALCAL_MODEL_AXIS6 && options->model != SCALCAL_MODEL_PAPER9)
    return SCALCAL_E_ARGUMENT;
  if (!magnitude_auto && !(options->magnitude > 0 && sc_finite(options->magnitude))) return SCALCAL_E_ARGUMENT;
  if (options->max_iterations < 1) return SCALCAL_E_ARGUMENT;
  if (!(options->noise >= 0 && sc_finite(options->noise))) return SCALCAL_E_ARGUMENT;
  if (!poses_finite(set)) return SCALCAL_E_NOT_FINITE;
  /* The host's rule for a log mostly in motion (README.md, "A stream that never stops"); a tumbling
   * set is motion by design, fitted on every sample. */
  if (!options->tumble && (uint64_t)set->windows_moving * 4 > (uint64_t)set->windows_judged * 3)
    return SCALCAL_E_MOVING;
  memset(&q, 0, sizeof q);
  q.set = set;
  q.magnitude = magnitude_auto ? 1 : options->magnitude;
  q.weight_by_samples = options->weight_by_samples;
  q.noise = options->noise;
  if (options->tumble) {
    q.tumbling = 1;
    q.weight_by_samples = 1; /* every sample counts once, as the host's per-sample fit */
    q.noise = 0;
    scalcal_tumble_noise(options->tumble, q.raw_noise);
  }
  status = choose(&q, options->model, magnitude_auto, r);
  if (status != SCALCAL_OK) return status;
  q.p = (int)r->model;
  status = start_and_check(&q, magnitude_auto);
  r->started = q.started;
  if (status != SCALCAL_OK) return status;
  sc_estimate(&q, options->max_iterations, X, r);
  memcpy(r->X, X, sizeof X);
  if (r->termination != SCALCAL_FIT_CONVERGED) return SCALCAL_E_NOT_CONVERGED;
  /* The layout judged again where the fit put the poses: a start that bent a flat or narrow layout
   * into a sphere leaves them in a small cap, which cannot carry the model (beyond the host). */
  r->fitted_condition = sc_fitted_condition(&q, X);
  if (!(r->fitted_condition <= SC_CARRY_CONDITION)) return SCALCAL_E_NOT_IDENTIFIABLE;
  memset(&out, 0, sizeof out);
  out.model = r->model;
  out.magnitude = q.magnitude;
  out.magnitude_auto = magnitude_auto;
  out.positions = set->count;
  {
    uint32_t i;
    for (i = 0; i < set->count; ++i) out.samples += set->poses[i].count;
  }
  status = compose(&q, X, &out);
  if (status != SCALCAL_OK) return status;
  if (q.tumbling) {
    sc_meter m;
    sc_meter_of(&q, X, &m);
    q.noise = sc_tumbling_noise(&q, &m);
  }
  sc_standard_errors(&q, X, &out, r);
  if (!calibration_finite(&out)) return SCALCAL_E_NOT_FINITE;
  if (!matrix_usable(&out)) return SCALCAL_E_DEGENERATE;
  *cal = out;
  return SCALCAL_OK;
}
