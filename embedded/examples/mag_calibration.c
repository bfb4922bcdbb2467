/* Worked example: a magnetometer calibrated where it lives, tumbling (scalcal/tumble.h). At start-up
 * the firmware loads its calibration record; when there is none, it asks the user to turn the device
 * slowly through every orientation, puts every sample into one of 64 cells (no sample is dropped,
 * nothing grows), and when the user is done (board_imu_read returns 0: a button, a timeout) fits the
 * cells, says how well the turning covered the sphere (D-efficiency of the cells against the
 * sphere's limit) and stores the record. A second turning gated by this calibration would leave
 * disturbances out (scalcal_tumble_gate; README.md "Tumbling mode"): a live device asks for it when
 * the first pass's residual RMS is well above its noise. Memory: all static, 64 cells and the
 * accumulator, about 2.7 KB in float. Board functions as imu_calibration.c's (board.h), the sample
 * being the magnetometer's; its ADC is a signed 16-bit one (the QMC5883L's). */
#include "board.h"
#include "scalcal/fit.h"
#include "scalcal/guidance.h"
#include "scalcal/record.h"
#include "scalcal/tumble.h"

#define CELLS 64

static scalcal_pose cells_storage[CELLS];
static scalcal_tumble tumbler;
static scalcal_calibration calibration;
static uint8_t record[SCALCAL_RECORD_SIZE];

static void say_number(const char* what, scalcal_real v) {
  char text[64];
  int k = 0, i;
  long whole;
  while (what[k] && k < 40) text[k] = what[k], ++k;
  text[k++] = ' ';
  if (v < 0) text[k++] = '-', v = -v;
  whole = (long)v;
  i = (int)((v - (scalcal_real)whole) * 1000 + 0.5f);
  if (i == 1000) ++whole, i = 0;
  {
    char digits[12];
    int n = 0;
    do digits[n++] = (char)('0' + whole % 10), whole /= 10;
    while (whole && n < 10);
    while (n > 0) text[k++] = digits[--n];
  }
  text[k++] = '.';
  text[k++] = (char)('0' + i / 100), text[k++] = (char)('0' + i / 10 % 10), text[k++] = (char)('0' + i % 10);
  text[k] = 0;
  board_say(text);
}

static scalcal_status tumbling_calibration(scalcal_calibration* cal) {
  scalcal_pose_set cells;
  scalcal_fit_options options;
  scalcal_fit_report report;
  scalcal_program_quality quality;
  scalcal_real raw[3];
  scalcal_status status;
  scalcal_pose_set_init(&cells, cells_storage, CELLS);
  scalcal_tumble_init(&tumbler, &cells, -32768, 32767); /* a component at the rail is saturated */
  board_say("calibration: turn the sensor slowly through every orientation");
  while (board_imu_read(raw)) scalcal_tumble_push(&tumbler, &cells, raw);
  scalcal_fit_options_default(&options);
  options.magnitude_auto = 1; /* the field's strength is not known: the correction maps to unit modulus */
  options.model = SCALCAL_MODEL_PAPER9;
  options.tumble = &tumbler;
  status = scalcal_fit(&cells, &options, cal, &report);
  if (status != SCALCAL_OK) return status;
  if (scalcal_program_quality_of(&cells, cal, report.model, &quality) == SCALCAL_OK)
    say_number("the turning is worth (D-efficiency)", quality.efficiency[SCALCAL_CRITERION_D]);
  return SCALCAL_OK;
}

int main(void) {
  scalcal_real raw[3], b[3];
  scalcal_status status = SCALCAL_E_RECORD;
  if (board_flash_read(record, sizeof record) == 0) status = scalcal_record_read(record, &calibration, 0);
  if (status != SCALCAL_OK) {
    status = tumbling_calibration(&calibration);
    if (status != SCALCAL_OK) {
      board_say(scalcal_status_text(status));
      return 1;
    }
    say_number("calibrated; offset x (counts)", calibration.offset[0]);
    say_number("offset y", calibration.offset[1]);
    say_number("offset z", calibration.offset[2]);
    say_number("field strength (counts)", calibration.nominal_gain);
    say_number("residual RMS (of the field)", calibration.residual_rms);
    scalcal_record_write(&calibration, 1, record);
    if (board_flash_write(record, sizeof record) != 0) board_say("could not store the calibration");
  }
  /* From here on, every sample as a unit vector's multiple (the field's strength is 1). */
  while (board_imu_read(raw)) scalcal_correct(&calibration, raw, b);
  return 0;
}
