/* The smallest board for the size report: the IMU is a memory-mapped register triple, the user
 * interface and flash do nothing. Only what the library and the example cost is left. */
#include "board.h"

#define IMU ((volatile int16_t*)0x40001000u)

int board_imu_read(scalcal_real raw[3]) {
  raw[0] = IMU[0], raw[1] = IMU[1], raw[2] = IMU[2];
  return IMU[3] != 0;
}
void board_sensor(scalcal_real* adc_min, scalcal_real* adc_max, scalcal_real* zero, scalcal_real* counts_per_g) {
  *adc_min = -32768, *adc_max = 32767, *zero = 0, *counts_per_g = 16384; /* an int16 +-2 g accelerometer */
}
void board_say(const char* text) { (void)text; }
int board_flash_read(uint8_t* bytes, uint32_t size) {
  (void)bytes, (void)size;
  return 1;
}
int board_flash_write(const uint8_t* bytes, uint32_t size) {
  (void)bytes, (void)size;
  return 0;
}
