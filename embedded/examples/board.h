/* What the worked example (imu_calibration.c) needs from the board: your firmware implements these
 * six functions over its IMU driver, display and flash (board_qemu.c does it over QEMU semihosting
 * and a real log; board_stub.c is the smallest possible, for the size report). */
#ifndef SCALCAL_EXAMPLE_BOARD_H
#define SCALCAL_EXAMPLE_BOARD_H

#include <stdint.h>

#include "scalcal/real.h"

/* The next raw sample of the accelerometer (counts), at the rate the detector was set up with;
 * 0 when there is none (end of a recording; a live sensor never returns 0). */
int board_imu_read(scalcal_real raw[3]);
/* The sensor's datasheet: the ADC's output range (a sample at either end is saturated) and the
 * nominal zero and sensitivity (counts at 0 g, counts per g), for guidance before the first fit. */
void board_sensor(scalcal_real* adc_min, scalcal_real* adc_max, scalcal_real* zero, scalcal_real* counts_per_g);
/* One line to the user (a display, a serial console, a phone over BLE). */
void board_say(const char* text);
/* The flash page that holds the calibration record: 0 on success. */
int board_flash_read(uint8_t* bytes, uint32_t size);
int board_flash_write(const uint8_t* bytes, uint32_t size);

#endif
