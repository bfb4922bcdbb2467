/* Test side only (host, float and double): a header as `scalcal export --format c` is to write it
 * (README.md, "The header of scalcal export --format c"), here tests/xsens_calibration.h, written
 * by hand from `scalcal calibrate --measurements data/xsens_acc.txt --magnitude 9.81744 --out
 * cal.json`, compiles with the library: its constants fill a scalcal_calibration, whose paper form
 * (gains, scale deviations, non-orthogonality) recomputed from offset and matrix alone must match
 * the header's own; its inline correction must match scalcal_correct on every sample of the log;
 * the flash record of it must read back. Usage: export_header_test LOG. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "log_reader.h"
#include "scalcal/calibration.h"
#include "scalcal/record.h"
#include "xsens_calibration.h"

int main(int argc, char** argv) {
  const scalcal_real offset[3] = SCALCAL_CAL_OFFSET;
  const scalcal_real matrix[3][3] = SCALCAL_CAL_MATRIX;
  const double scale_deviation[3] = SCALCAL_CAL_SCALE_DEVIATION, gamma[3] = SCALCAL_CAL_NONORTHOGONALITY;
  const double bias_std[3] = SCALCAL_CAL_BIAS_STD;
  /* float: the header's 17 digits rounded to float; the paper form follows to single precision. */
  const double tolerance = sizeof(scalcal_real) == 8 ? 1e-12 : 2e-5;
  scalcal_calibration cal, back;
  uint8_t record[SCALCAL_RECORD_SIZE];
  test_log log;
  double worst = 0;
  int k, row, rows;
  CHECK(SCALCAL_CAL_FORMAT == 1, "format %d", SCALCAL_CAL_FORMAT);
  CHECK(scalcal_calibration_from_matrix(&cal, (scalcal_model)SCALCAL_CAL_MODEL, offset, &matrix[0][0],
                                        (scalcal_real)SCALCAL_CAL_MAGNITUDE, SCALCAL_CAL_MAGNITUDE_AUTO,
                                        (scalcal_real)SCALCAL_CAL_NOMINAL_GAIN) == SCALCAL_OK,
        "from the header's matrix");
  for (k = 0; k < 3; ++k) {
    CHECK(fabs(cal.scale_deviation[k] - scale_deviation[k]) < tolerance, "scale deviation %d: %.17g header %.17g", k,
          (double)cal.scale_deviation[k], scale_deviation[k]);
    CHECK(fabs(cal.nonorthogonality[k] - gamma[k]) < tolerance, "gamma %d: %.17g header %.17g", k,
          (double)cal.nonorthogonality[k], gamma[k]);
    CHECK(bias_std[k] > 0, "bias std %d", k);
  }
  if (argc < 2 || test_log_read(argv[1], 0, &log)) return 2;
  for (row = 0; row < log.rows; ++row) {
    const scalcal_real raw[3] = {(scalcal_real)log.x[row][0], (scalcal_real)log.x[row][1], (scalcal_real)log.x[row][2]};
    scalcal_real a[3];
    float b[3];
    const float rawf[3] = {(float)log.x[row][0], (float)log.x[row][1], (float)log.x[row][2]};
    scalcal_correct(&cal, raw, a);
    scalcal_cal_apply(rawf, b);
    for (k = 0; k < 3; ++k) worst = fabs(a[k] - b[k]) > worst ? fabs(a[k] - b[k]) : worst;
  }
  /* The header's function works in float: within float's rounding of values near 10 m/s^2. */
  CHECK(worst < 1e-4, "the header's correction and the library's differ by %g m/s^2", worst);
  CHECK(scalcal_record_write(&cal, 3, record) == SCALCAL_OK && scalcal_record_read(record, &back, 0) == SCALCAL_OK,
        "record round trip");
  for (k = 0; k < 3; ++k) CHECK(fabs(back.offset[k] - offset[k]) <= 1e-7 * fabs(offset[k]), "record offset %d", k);
  rows = log.rows;
  test_log_free(&log);
  printf("%s export header test (%s, %d rows): %d failures\n", failures ? "FAILED" : "passed",
         sizeof(scalcal_real) == 8 ? "double" : "float", rows, failures);
  return failures ? 1 : 0;
}
