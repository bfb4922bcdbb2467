/* Test side only: semihost.h over stdio, for the host build of the QEMU test program. */
#include <stdio.h>
#include <stdlib.h>

#include "semihost.h"

static FILE* files[4];

int semihost_open(const char* path) {
  int k;
  for (k = 0; k < 4; ++k)
    if (!files[k]) {
      files[k] = fopen(path, "rb");
      return files[k] ? k : -1;
    }
  return -1;
}
long semihost_read(int handle, void* buffer, long bytes) {
  return (long)fread(buffer, 1, (size_t)bytes, files[handle]);
}
void semihost_close(int handle) {
  fclose(files[handle]);
  files[handle] = 0;
}
void semihost_write(const char* text) { fputs(text, stdout); }
void semihost_exit(int status) { exit(status); }
uint32_t stack_peak_bytes(void) { return 0; }
