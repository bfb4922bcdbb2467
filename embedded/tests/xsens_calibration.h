/* scalcal calibration: the layout `scalcal export cal.json --format c` is to write (embedded/README.md),
 * written by hand for the tests from `scalcal calibrate --measurements data/xsens_acc.txt --magnitude 9.81744
 * --sensor "Xsens accelerometer (IMU-TK test log)" --units counts,m/s^2 --out cal.json` (scalcal 0.1, commit
 * 9c0d423541b3). Sensor: Xsens accelerometer (IMU-TK test log).
 * physical = SCALCAL_CAL_MATRIX (raw - SCALCAL_CAL_OFFSET), the paper's convention (phi_kj = phi_jk).
 * (The clang-format markers are this fixture's, for the repository's format check; the export has none.) */
#ifndef SCALCAL_CAL_H
#define SCALCAL_CAL_H
/* clang-format off */
#define SCALCAL_CAL_FORMAT 1                /* this layout's version */
#define SCALCAL_CAL_MODEL 9                 /* parameters: 3 bias3, 6 axis6, 9 paper9 */
#define SCALCAL_CAL_MODEL_NAME "paper9"
#define SCALCAL_CAL_INSTRUMENT "accel"      /* accel, mag or gyro */
#define SCALCAL_CAL_SENSOR "Xsens accelerometer (IMU-TK test log)"
#define SCALCAL_CAL_UNITS_RAW "counts"
#define SCALCAL_CAL_UNITS_PHYSICAL "m/s^2"
#define SCALCAL_CAL_MAGNITUDE 9.8174399999999995      /* |I| in physical units; 1 with --magnitude auto */
#define SCALCAL_CAL_MAGNITUDE_AUTO 0                     /* 1: the field's strength was unknown (unit modulus) */
#define SCALCAL_CAL_NOMINAL_GAIN 413.72733552991048  /* raw units per physical unit */
#define SCALCAL_CAL_OFFSET {33123.827057277347, 33275.153359489552, 32364.489921490076}  /* raw units */
#define SCALCAL_CAL_MATRIX {{0.002412975497765541, -4.168329997236012e-06, -1.1070834280804343e-05}, {-4.1450382554041013e-06, 0.0024268720525120867, -2.5734579305386963e-05}, {-1.1075616423444857e-05, -2.589036543728228e-05, 0.0024123347543222834}}  /* physical per raw unit, by rows */
#define SCALCAL_CAL_SCALE_DEVIATION {0.0017253507412189339, -0.0038720775505468596, 0.0021580546723189986}  /* relative to the nominal gain */
#define SCALCAL_CAL_NONORTHOGONALITY {0.0035334235221505961, 0.021350794384426986, 0.0092161048764849759}  /* gamma_xy, gamma_yz, gamma_zx, rad */
#define SCALCAL_CAL_BIAS_STD {0.24498969620573058, 0.13735111998154412, 0.14992281344257835}  /* raw units; -1: not estimable */
#define SCALCAL_CAL_SCALE_DEVIATION_STD {4.6109267268695797e-05, 3.7743997148076621e-05, 3.3573022027023596e-05}
#define SCALCAL_CAL_NONORTHOGONALITY_STD {0.00013667995908375424, 0.00011985902079075046, 0.00047659176816223711}  /* rad */
#define SCALCAL_CAL_RESIDUAL_RMS 0.00097897609335365261  /* physical units */
#define SCALCAL_CAL_POSITIONS 38
#define SCALCAL_CAL_SAMPLES 32790
/* clang-format on */
static inline void scalcal_cal_apply(const float raw[3], float physical[3]) {
  static const float o[3] = SCALCAL_CAL_OFFSET, m[3][3] = SCALCAL_CAL_MATRIX;
  const float d[3] = {raw[0] - o[0], raw[1] - o[1], raw[2] - o[2]};
  int i;
  for (i = 0; i < 3; ++i) physical[i] = m[i][0] * d[0] + m[i][1] * d[1] + m[i][2] * d[2];
}
#endif
