/* Worked example: an accelerometer calibrated where it lives. At start-up the firmware loads its
 * calibration record from flash; when there is none (or the user asks), it guides the user through
 * still poses: it detects each pose as the samples arrive, fits after every new pose once there are
 * enough, tells the user how good the poses are against the best any program can be (D-efficiency
 * on the sphere) and which way to turn next, stops when the poses are good enough, and stores the
 * record. Every sample after that is corrected with physical = matrix (raw - offset).
 * Memory: everything is static (no malloc): 64 poses and the detector, about 5.4 KB in float. */
#include <string.h>

#include "board.h"
#include "scalcal/detector.h"
#include "scalcal/fit.h"
#include "scalcal/guidance.h"
#include "scalcal/record.h"

#define RATE_HZ 100      /* the IMU's output data rate */
#define GOOD_ENOUGH 0.9f /* stop at this D-efficiency against the sphere's limit */
#define MIN_POSES 12     /* and at least this many poses (paper9 needs 9; a few spare give errors) */

static scalcal_pose poses[SCALCAL_MAX_POSES];
static scalcal_detector detector;
static scalcal_calibration calibration;
static uint8_t record[SCALCAL_RECORD_SIZE];

/* "turn the sensor so that +x+y points up": the direction to ask for, in words. */
static void say_direction(const scalcal_real d[3]) {
  static const char* axis[3][2] = {{"+x", "-x"}, {"+y", "-y"}, {"+z", "-z"}};
  char text[64] = "next: turn so that ";
  int k, any = 0;
  for (k = 0; k < 3; ++k)
    if (d[k] > 0.3f || d[k] < -0.3f) {
      if (any++) strcat(text, " ");
      strcat(text, axis[k][d[k] > 0 ? 0 : 1]);
    }
  strcat(text, " points up");
  board_say(text);
}

static void say_number(const char* what, scalcal_real v, const char* unit) {
  char text[64];
  int k = (int)strlen(what), i = (int)(v * 1000 + 0.5f);
  memcpy(text, what, (size_t)k);
  text[k++] = ' ';
  text[k++] = (char)('0' + i / 1000 % 10), text[k++] = '.';
  text[k++] = (char)('0' + i / 100 % 10), text[k++] = (char)('0' + i / 10 % 10), text[k++] = (char)('0' + i % 10);
  strcpy(text + k, unit);
  board_say(text);
}

/* One fit of the poses so far; OK when it converged to a calibration the host would write. */
static scalcal_status try_fit(const scalcal_pose_set* set, scalcal_calibration* cal, scalcal_model* model) {
  scalcal_fit_options options;
  scalcal_fit_report report;
  scalcal_status status;
  scalcal_fit_options_default(&options);
  options.magnitude = 9.80665f; /* m/s^2: the correction maps counts to m/s^2 */
  options.model = SCALCAL_MODEL_PAPER9;
  status = scalcal_fit(set, &options, cal, &report);
  *model = report.model;
  return status;
}

/* The guided session: returns SCALCAL_OK with *cal filled, or why it stopped. */
static scalcal_status guided_calibration(scalcal_calibration* cal) {
  scalcal_calibration guide;
  scalcal_real zero[3], nominal[9] = {0}, counts_per_g;
  scalcal_detector_options options;
  scalcal_pose_set set;
  scalcal_real raw[3];
  scalcal_status status = SCALCAL_E_TOO_FEW_POSES;
  int have_fit = 0;
  scalcal_detector_options_default(&options, RATE_HZ);
  board_sensor(&options.adc_min, &options.adc_max, &zero[0], &counts_per_g); /* at its rails: saturated */
  /* Before any fit the directions come from the datasheet: physical = (raw - zero) g / counts_per_g. */
  zero[1] = zero[2] = zero[0];
  nominal[0] = nominal[4] = nominal[8] = 9.80665f / counts_per_g;
  scalcal_calibration_from_matrix(&guide, SCALCAL_MODEL_PAPER9, zero, nominal, 9.80665f, 0, 1);
  scalcal_pose_set_init(&set, poses, SCALCAL_MAX_POSES);
  scalcal_detector_init(&detector, &options);
  board_say("calibration: hold the sensor still in different orientations, one at a time");
  while (board_imu_read(raw)) {
    scalcal_program_quality quality;
    scalcal_model model = SCALCAL_MODEL_PAPER9;
    uint32_t best;
    const scalcal_event event = scalcal_detector_push(&detector, &set, raw);
    if (event == SCALCAL_EVENT_FULL) break;
    if (event != SCALCAL_EVENT_POSE) continue;
    board_say("pose stored");
    if (set.count >= 9 && (status = try_fit(&set, cal, &model)) == SCALCAL_OK) {
      have_fit = 1;
      guide = *cal;
      scalcal_program_quality_of(&set, cal, model, &quality);
      say_number("poses so far are worth (D-efficiency)", quality.efficiency[SCALCAL_CRITERION_D], "");
      if (set.count >= MIN_POSES && quality.efficiency[SCALCAL_CRITERION_D] >= GOOD_ENOUGH) return SCALCAL_OK;
    }
    if (scalcal_next_pose(&set, &guide, SCALCAL_MODEL_PAPER9, SCALCAL_CRITERION_D, scalcal_candidates26, 26, &best,
                          0) == SCALCAL_OK)
      say_direction(scalcal_candidates26[best]);
  }
  scalcal_detector_finish(&detector, &set);
  if (set.count >= 9) {
    scalcal_model model;
    status = try_fit(&set, cal, &model);
    have_fit = status == SCALCAL_OK;
  }
  if (!have_fit && scalcal_detector_state(&detector) == SCALCAL_STREAM_NO_FLOOR)
    board_say("no still moment found: hold the sensor still for a second at a time");
  return have_fit ? SCALCAL_OK : status;
}

int main(void) {
  scalcal_real raw[3], g[3];
  scalcal_status status = SCALCAL_E_RECORD;
  if (board_flash_read(record, sizeof record) == 0) status = scalcal_record_read(record, &calibration, 0);
  if (status != SCALCAL_OK) {
    status = guided_calibration(&calibration);
    if (status != SCALCAL_OK) {
      board_say(scalcal_status_text(status));
      return 1;
    }
    say_number("calibrated; residual (m/s^2)", calibration.residual_rms, "");
    scalcal_record_write(&calibration, 1, record);
    if (board_flash_write(record, sizeof record) != 0) board_say("could not store the calibration");
  }
  /* From here on, every sample in m/s^2. */
  while (board_imu_read(raw)) scalcal_correct(&calibration, raw, g);
  return 0;
}
