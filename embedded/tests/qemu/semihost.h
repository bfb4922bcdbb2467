/* Test side only: the few ARM semihosting calls the QEMU test needs (open, length, read, write to the
 * console, exit), and the same interface on the host over stdio (host_io.c), so that one test
 * program runs on both and prints the same bytes. */
#ifndef SCALCAL_TEST_SEMIHOST_H
#define SCALCAL_TEST_SEMIHOST_H

#include <stdint.h>

int semihost_open(const char* path);                      /* a handle, or -1 */
long semihost_read(int handle, void* buffer, long bytes); /* bytes read, 0 at the end */
void semihost_close(int handle);
void semihost_write(const char* text); /* to the console */
void semihost_exit(int status);
uint32_t stack_peak_bytes(void); /* 0 on the host */

#endif
