/* Test side only (host): a real log fed sample by sample to the embedded library, printed as
 * `key value...` lines (17 significant digits) for tests/compare_cli.py to compare with
 * `scalcal calibrate --json`. Poses come either from the CLI's own intervals (--intervals FILE:
 * lines `start end` in seconds, inclusive; `break FIRST LAST` for the samples inside an interval
 * that are not its, as sample indices of the log from 0; `exclude LINE` for the samples the CLI
 * left out as outliers), or from the library's streaming detector (--detect). --noise gives the fit
 * one sample's noise instead of its own first-order estimate (to compare the error model with the
 * CLI's on the same noise). --tumble feeds every sample to the tumbling accumulator (cells of the
 * set's capacity, scalcal/tumble.h) and fits them in tumbling mode; --gate S then feeds the log again
 * (--passes N in all, default 2) with samples beyond S times the last fit's noise (second differences:
 * a disturbance does not inflate it as it does the residuals) left out, and fits again. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "log_reader.h"
#include "scalcal/detector.h"
#include "scalcal/fit.h"
#include "scalcal/guidance.h"
#include "scalcal/rate_table.h"
#include "scalcal/tumble.h"

#define MAX_INTERVALS 4096

/* The stream indices of each pose stored (the fit does not need them; the comparison does). */
static uint32_t pose_first[MAX_INTERVALS], pose_last[MAX_INTERVALS];

static void print_vec(const char* key, const scalcal_real* v, int n) {
  int k;
  printf("%s", key);
  for (k = 0; k < n; ++k) printf(" %.17g", (double)v[k]);
  printf("\n");
}

typedef struct {
  int count;
  double start[MAX_INTERVALS], end[MAX_INTERVALS];
  int excluded_count;
  int excluded[65536];
  int break_count;
  int break_first[MAX_INTERVALS], break_last[MAX_INTERVALS];
} given_intervals;

static int read_intervals(const char* path, given_intervals* g) {
  FILE* f = fopen(path, "r");
  char word[64];
  if (!f) return fprintf(stderr, "%s: cannot open\n", path), 1;
  g->count = g->excluded_count = g->break_count = 0;
  while (fscanf(f, "%63s", word) == 1) {
    if (!strcmp(word, "exclude")) {
      if (fscanf(f, "%d", &g->excluded[g->excluded_count]) == 1 && g->excluded_count < 65535) g->excluded_count++;
    } else if (!strcmp(word, "break")) {
      if (fscanf(f, "%d %d", &g->break_first[g->break_count], &g->break_last[g->break_count]) == 2 &&
          g->break_count < MAX_INTERVALS - 1)
        g->break_count++;
    } else if (g->count < MAX_INTERVALS) {
      g->start[g->count] = strtod(word, 0);
      if (fscanf(f, "%lf", &g->end[g->count]) == 1) g->count++;
    }
  }
  fclose(f);
  return 0;
}

static int is_excluded(const given_intervals* g, int line, int row) {
  int k;
  for (k = 0; k < g->excluded_count; ++k)
    if (g->excluded[k] == line) return 1;
  for (k = 0; k < g->break_count; ++k)
    if (row >= g->break_first[k] && row <= g->break_last[k]) return 1;
  return 0;
}

static int finite3(const double* x) { return isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]); }

/* Poses from the CLI's intervals: every finite, not excluded sample inside interval k goes to pose k. */
static int feed_given(const test_log* log, const given_intervals* g, scalcal_pose_set* set) {
  static scalcal_pose_sum pose;
  int row, k = 0;
  for (k = 0; k < g->count; ++k) {
    scalcal_pose_sum_clear(&pose);
    for (row = 0; row < log->rows; ++row) {
      scalcal_real x[3];
      if (!(log->t[row] >= g->start[k] && log->t[row] <= g->end[k])) continue;
      if (!finite3(log->x[row]) || !isfinite(log->t[row]) || is_excluded(g, log->line[row], row)) continue;
      x[0] = (scalcal_real)log->x[row][0], x[1] = (scalcal_real)log->x[row][1], x[2] = (scalcal_real)log->x[row][2];
      scalcal_pose_sum_add(set, &pose, x, (uint32_t)row);
    }
    pose_first[set->count] = pose.first, pose_last[set->count] = pose.last;
    if (scalcal_pose_set_append(set, &pose) != SCALCAL_OK) return 1;
  }
  return 0;
}

/* Poses from the streaming detector. */
static int feed_detector(const test_log* log, double rate, scalcal_pose_set* set) {
  static scalcal_detector det;
  scalcal_detector_options o;
  int row;
  scalcal_detector_options_default(&o, (scalcal_real)rate);
  if (scalcal_detector_init(&det, &o) != SCALCAL_OK) return 1;
  for (row = 0; row < log->rows; ++row) {
    scalcal_real x[3];
    x[0] = (scalcal_real)log->x[row][0], x[1] = (scalcal_real)log->x[row][1], x[2] = (scalcal_real)log->x[row][2];
    if (scalcal_detector_push(&det, set, x) == SCALCAL_EVENT_POSE)
      pose_first[set->count - 1] = det.closed_first, pose_last[set->count - 1] = det.closed_last;
  }
  if (scalcal_detector_finish(&det, set) == SCALCAL_EVENT_POSE)
    pose_first[set->count - 1] = det.closed_first, pose_last[set->count - 1] = det.closed_last;
  printf("detector_floor %.17g\n", (double)det.floor);
  printf("detector_threshold %.17g\n", (double)det.threshold);
  printf("detector_window %u\n", (unsigned)(det.block_samples * SCALCAL_DETECTOR_BLOCKS));
  printf("detector_short_runs %u\n", (unsigned)det.short_runs);
  printf("detector_state %s\n", scalcal_detector_state_text(&det));
  printf("detector_windows %u %u\n", (unsigned)set->windows_judged, (unsigned)set->windows_moving);
  return 0;
}

/* Every sample to the tumbling accumulator (gated by cal when not null). */
static int feed_tumble(const test_log* log, scalcal_tumble* t, scalcal_pose_set* set, const scalcal_calibration* cal,
                       scalcal_real limit) {
  int row;
  if (scalcal_tumble_init(t, set, 0, 0) != SCALCAL_OK) return 1;
  scalcal_tumble_gate(t, cal, limit);
  for (row = 0; row < log->rows; ++row) {
    scalcal_real x[3];
    x[0] = (scalcal_real)log->x[row][0], x[1] = (scalcal_real)log->x[row][1], x[2] = (scalcal_real)log->x[row][2];
    scalcal_tumble_push(t, set, x);
  }
  printf("tumble_samples %u\ntumble_invalid %u\ntumble_disturbed %u\ntumble_merges %u\ntumble_cells %u\n",
         (unsigned)t->samples, (unsigned)t->invalid, (unsigned)t->disturbed, (unsigned)t->merges,
         (unsigned)set->count);
  return 0;
}

static void print_result(const scalcal_pose_set* set, const scalcal_calibration* c, const scalcal_fit_report* r) {
  scalcal_program_quality pq;
  uint32_t i, best;
  scalcal_real after;
  const int p = (int)r->model;
  print_vec("offset", c->offset, 3);
  print_vec("matrix", &c->matrix[0][0], 9);
  print_vec("scale_deviation", c->scale_deviation, 3);
  print_vec("nonorthogonality", c->nonorthogonality, 3);
  print_vec("gain", c->gain, 3);
  print_vec("nominal_gain", &c->nominal_gain, 1);
  print_vec("bias_std", c->bias_std, 3);
  print_vec("scale_deviation_std", c->scale_deviation_std, 3);
  print_vec("nonorthogonality_std", c->nonorthogonality_std, 3);
  print_vec("gain_std", c->gain_std, 3);
  print_vec("nominal_gain_std", &c->nominal_gain_std, 1);
  print_vec("noise", &c->noise, 1);
  print_vec("residual_rms", &c->residual_rms, 1);
  print_vec("predicted_std", r->predicted_std, p);
  print_vec("achieved_std", r->achieved_std, p);
  print_vec("chi_square", &r->chi_square, 1);
  printf("noise_source %d\n", (int)r->noise_source);
  printf("error_model %d %d\n", r->error_model, r->error_model_iterations);
  print_vec("between_std", &r->between_std, 1);
  print_vec("within_std", &r->within_std, 1);
  print_vec("model_std", r->model_std, p);
  printf("samples %u\n", (unsigned)c->samples);
  if (scalcal_program_quality_of(set, c, r->model, &pq) == SCALCAL_OK) {
    print_vec("program_value", pq.value, 4);
    print_vec("program_efficiency", pq.efficiency, 4);
    print_vec("program_condition", &pq.condition, 1);
  }
  for (i = 0; i < 4; ++i)
    if (scalcal_next_pose(set, c, r->model, (scalcal_criterion)i, scalcal_candidates26, 26, &best, &after) ==
        SCALCAL_OK)
      printf("next_pose %u %u %.17g\n", (unsigned)i, (unsigned)best, (double)after);
  for (i = 0; i < set->count; ++i) {
    scalcal_real m[3];
    scalcal_pose_mean(set, i, m);
    printf("pose %u %u %u %u %.17g %.17g %.17g\n", (unsigned)i, (unsigned)pose_first[i], (unsigned)pose_last[i],
           (unsigned)set->poses[i].count, (double)m[0], (double)m[1], (double)m[2]);
  }
}

/* A gyro's rate table (scalcal/rate_table.h): the fit and its report. */
static int run_rate_table(const scalcal_pose_set* set, scalcal_model model, double table_rate) {
  static scalcal_rate_table_report rr;
  scalcal_rate_table_options ro;
  scalcal_calibration c;
  scalcal_status s;
  uint32_t i;
  scalcal_rate_table_options_default(&ro);
  ro.model = model;
  ro.rate = (scalcal_real)table_rate;
  s = scalcal_fit_rate_table(set, &ro, &c, &rr);
  printf("status %d %s\n", (int)s, scalcal_status_text(s));
  printf("model %d\nsegments %u\nrests %u\niterations %d\ntermination %d\n", (int)rr.model, (unsigned)rr.segments,
         (unsigned)rr.rests, rr.iterations, (int)rr.termination);
  printf("rest_flags");
  for (i = 0; i < set->count; ++i) printf(" %d", rr.rest[i]);
  printf("\n");
  print_vec("condition", &rr.condition, 1);
  print_vec("parameters", rr.parameters, 9);
  print_vec("standard_error", rr.standard_error, 9);
  print_vec("predicted_std", rr.predicted_std, 9);
  print_vec("scales", &rr.segment_scale, 2);
  if (s != SCALCAL_OK) return 0;
  print_vec("offset", c.offset, 3);
  print_vec("matrix", &c.matrix[0][0], 9);
  print_vec("scale_deviation", c.scale_deviation, 3);
  print_vec("nonorthogonality", c.nonorthogonality, 3);
  print_vec("gain", c.gain, 3);
  print_vec("bias_std", c.bias_std, 3);
  print_vec("scale_deviation_std", c.scale_deviation_std, 3);
  print_vec("nonorthogonality_std", c.nonorthogonality_std, 3);
  print_vec("noise", &c.noise, 1);
  return 0;
}

int main(int argc, char** argv) {
  static scalcal_pose storage[MAX_INTERVALS];
  static given_intervals given;
  scalcal_pose_set set;
  scalcal_fit_options o;
  scalcal_calibration cal;
  scalcal_fit_report report;
  scalcal_status s;
  test_log log;
  const char *path = 0, *intervals = 0;
  double rate = 0;
  int k, detect = 0, tumble = 0, capacity = SCALCAL_MAX_POSES;
  double gate = 0, table_rate = 0;
  int passes = 2;
  static scalcal_tumble tumbler;
  scalcal_fit_options_default(&o);
  for (k = 1; k < argc; ++k) {
    if (!strcmp(argv[k], "--rate") && k + 1 < argc)
      rate = atof(argv[++k]);
    else if (!strcmp(argv[k], "--magnitude") && k + 1 < argc) {
      ++k;
      if (!strcmp(argv[k], "auto"))
        o.magnitude_auto = 1;
      else
        o.magnitude = (scalcal_real)atof(argv[k]);
    } else if (!strcmp(argv[k], "--model") && k + 1 < argc) {
      ++k;
      o.model = !strcmp(argv[k], "paper9")  ? SCALCAL_MODEL_PAPER9
                : !strcmp(argv[k], "axis6") ? SCALCAL_MODEL_AXIS6
                : !strcmp(argv[k], "bias3") ? SCALCAL_MODEL_BIAS3
                                            : SCALCAL_MODEL_AUTO;
    } else if (!strcmp(argv[k], "--intervals") && k + 1 < argc)
      intervals = argv[++k];
    else if (!strcmp(argv[k], "--capacity") && k + 1 < argc)
      capacity = atoi(argv[++k]);
    else if (!strcmp(argv[k], "--noise") && k + 1 < argc)
      o.noise = (scalcal_real)atof(argv[++k]);
    else if (!strcmp(argv[k], "--detect"))
      detect = 1;
    else if (!strcmp(argv[k], "--tumble"))
      tumble = 1;
    else if (!strcmp(argv[k], "--gate") && k + 1 < argc)
      gate = atof(argv[++k]);
    else if (!strcmp(argv[k], "--passes") && k + 1 < argc)
      passes = atoi(argv[++k]);
    else if (!strcmp(argv[k], "--rate-table") && k + 1 < argc)
      table_rate = atof(argv[++k]);
    else if (!strcmp(argv[k], "--weights-samples"))
      o.weight_by_samples = 1;
    else
      path = argv[k];
  }
  if (!path || (!intervals && !detect && !tumble)) {
    fprintf(stderr,
            "usage: host_run LOG [--rate HZ] --magnitude M|auto [--model NAME] (--intervals FILE | --detect)\n");
    return 2;
  }
  if (capacity < 1 || capacity > MAX_INTERVALS) return 2;
  if (test_log_read(path, rate, &log)) return 2;
  if (rate <= 0 && log.rows > 1) {
    /* the median time step, as the CLI's sample period */
    rate = 1 / ((log.t[log.rows - 1] - log.t[0]) / (log.rows - 1));
  }
  scalcal_pose_set_init(&set, storage, (uint32_t)capacity);
  if (tumble) {
    if (feed_tumble(&log, &tumbler, &set, 0, 0)) return 2;
    o.tumble = &tumbler;
  } else if (intervals) {
    if (read_intervals(intervals, &given) || feed_given(&log, &given, &set)) return 2;
  } else if (feed_detector(&log, rate, &set)) {
    return 2;
  }
  printf("precision %s\n", sizeof(scalcal_real) == 8 ? "double" : "float");
  printf("poses %u\n", (unsigned)set.count);
  if (table_rate > 0) {
    k = run_rate_table(&set, o.model, table_rate);
    test_log_free(&log);
    return k;
  }
  s = scalcal_fit(&set, &o, &cal, &report);
  for (k = 2; tumble && gate > 0 && k <= passes && s == SCALCAL_OK; ++k) { /* a pass gated by the last */
    static scalcal_calibration previous;
    previous = cal;
    printf("pass_offset %d %.17g %.17g %.17g\n", k - 1, (double)cal.offset[0], (double)cal.offset[1],
           (double)cal.offset[2]);
    if (feed_tumble(&log, &tumbler, &set, &previous, (scalcal_real)gate * previous.noise / previous.magnitude))
      return 2;
    s = scalcal_fit(&set, &o, &cal, &report);
  }
  printf("status %d %s\n", (int)s, scalcal_status_text(s));
  printf("model %d\n", (int)report.model);
  printf("started %d\n", report.started);
  printf("iterations %d\n", report.iterations);
  printf("termination %d\n", (int)report.termination);
  print_vec("condition", &report.condition, 1);
  print_vec("fitted_condition", &report.fitted_condition, 1);
  print_vec("X", report.X, report.model ? (int)report.model : 0);
  if (s == SCALCAL_OK) print_result(&set, &cal, &report);
  test_log_free(&log);
  return 0;
}
