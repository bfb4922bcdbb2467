/* Test side only: ARM semihosting (BKPT 0xAB, operation in r0, parameter block in r1). */
#include "semihost.h"

#include <string.h>

static int call(int op, void* arg) {
  register int r0 __asm__("r0") = op;
  register void* r1 __asm__("r1") = arg;
  __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

int semihost_open(const char* path) {
  uint32_t block[3] = {(uint32_t)path, 0 /* "r" */, (uint32_t)strlen(path)};
  return call(0x01, block);
}

long semihost_read(int handle, void* buffer, long bytes) {
  uint32_t block[3] = {(uint32_t)handle, (uint32_t)buffer, (uint32_t)bytes};
  return bytes - call(0x06, block); /* the call returns the bytes NOT read */
}

void semihost_close(int handle) {
  uint32_t block[1] = {(uint32_t)handle};
  call(0x02, block);
}

void semihost_write(const char* text) { call(0x04, (void*)text); }

void semihost_exit(int status) {
  /* SYS_EXIT_EXTENDED with ADP_Stopped_ApplicationExit and the status. */
  uint32_t block[2] = {0x20026u, (uint32_t)status};
  call(0x20, block);
  for (;;) {
  }
}
