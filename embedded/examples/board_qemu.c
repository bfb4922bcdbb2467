/* The example's board under QEMU: the IMU replays a real log (t ix iy iz per line, read by
 * semihosting), the user interface is the semihosting console, the flash a RAM page. */
#include <string.h>

#include "../tests/qemu/semihost.h"
#include "board.h"

#ifndef LOG_PATH
#define LOG_PATH "xsens_acc.txt"
#endif

static int handle = -2;
static char buffer[1024];
static long have, at;
static uint8_t flash[128];
static int flash_written;

/* The next byte of the log, or -1 at its end. */
static int next_byte(void) {
  if (at == have) {
    have = semihost_read(handle, buffer, sizeof buffer);
    at = 0;
    if (have <= 0) return -1;
  }
  return (unsigned char)buffer[at++];
}

/* A decimal number (digits, point, exponent) as the log writes it. */
static int next_number(scalcal_real* out) {
  static const scalcal_real tens[9] = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f, 1e6f, 1e7f, 1e8f};
  int c = next_byte(), negative = 0, e = 0, eneg = 0, exponent = 0, digits = 0;
  scalcal_real v = 0;
  while (c == ' ' || c == '\n' || c == '\r' || c == '\t') c = next_byte();
  if (c < 0) return 0;
  if (c == '-') negative = 1, c = next_byte();
  for (; c >= '0' && c <= '9'; c = next_byte(), ++digits) v = v * 10 + (scalcal_real)(c - '0');
  if (c == '.')
    for (c = next_byte(); c >= '0' && c <= '9'; c = next_byte(), --exponent) v = v * 10 + (scalcal_real)(c - '0');
  if (c == 'e' || c == 'E') {
    c = next_byte();
    if (c == '-' || c == '+') eneg = c == '-', c = next_byte();
    for (; c >= '0' && c <= '9'; c = next_byte()) e = e * 10 + (c - '0');
    exponent += eneg ? -e : e;
  }
  while (exponent > 0) v *= tens[exponent > 8 ? 8 : exponent], exponent -= exponent > 8 ? 8 : exponent;
  while (exponent < 0) v /= tens[-exponent > 8 ? 8 : -exponent], exponent += -exponent > 8 ? 8 : -exponent;
  *out = negative ? -v : v;
  return digits > 0;
}

int board_imu_read(scalcal_real raw[3]) {
  scalcal_real t;
  if (handle == -2) handle = semihost_open(LOG_PATH);
  if (handle < 0) return 0;
  return next_number(&t) && next_number(&raw[0]) && next_number(&raw[1]) && next_number(&raw[2]);
}

/* The Xsens log's ADC: unsigned 16 bits, zero g near 32768, about 413 counts per g (its datasheet's
 * nominal values would do as well: guidance only needs directions roughly right). */
void board_sensor(scalcal_real* adc_min, scalcal_real* adc_max, scalcal_real* zero, scalcal_real* counts_per_g) {
  *adc_min = 0, *adc_max = 65535, *zero = 32768, *counts_per_g = 413;
}

void board_say(const char* text) {
  semihost_write(text);
  semihost_write("\n");
}

int board_flash_read(uint8_t* bytes, uint32_t size) {
  if (!flash_written || size > sizeof flash) return 1;
  memcpy(bytes, flash, size);
  return 0;
}

int board_flash_write(const uint8_t* bytes, uint32_t size) {
  if (size > sizeof flash) return 1;
  memcpy(flash, bytes, size);
  flash_written = 1;
  return 0;
}
