/* Test side only: reset for a Cortex-M4F on QEMU's mps2-an386: the vector table, .data copied and
 * .bss zeroed, the FPU enabled (CPACR, CP10 and CP11 full access), the stack filled with a pattern
 * (to measure its peak use), main, and the semihosting exit with main's status. */
#include <stdint.h>

#include "semihost.h"

extern uint32_t _data_load, _data_start, _data_end, _bss_start, _bss_end, _stack_top, _stack_size;
int main(void);
void reset_handler(void);
static void fault_handler(void) { semihost_exit(3); }

__attribute__((section(".vectors"), used)) static const uintptr_t vectors[16] = {(uintptr_t)&_stack_top,
                                                                                 (uintptr_t)reset_handler,
                                                                                 (uintptr_t)fault_handler,
                                                                                 (uintptr_t)fault_handler,
                                                                                 (uintptr_t)fault_handler,
                                                                                 (uintptr_t)fault_handler,
                                                                                 (uintptr_t)fault_handler,
                                                                                 0,
                                                                                 0,
                                                                                 0,
                                                                                 0,
                                                                                 (uintptr_t)fault_handler,
                                                                                 (uintptr_t)fault_handler,
                                                                                 0,
                                                                                 (uintptr_t)fault_handler,
                                                                                 (uintptr_t)fault_handler};

#define STACK_PATTERN 0x5CA1CA1Bu

uint32_t stack_peak_bytes(void) {
  const uint32_t* p = (const uint32_t*)((uintptr_t)&_stack_top - (uintptr_t)&_stack_size);
  while (p < (const uint32_t*)&_stack_top && *p == STACK_PATTERN) ++p;
  return (uint32_t)((uintptr_t)&_stack_top - (uintptr_t)p);
}

/* "stack_peak_bytes N" on the console (the QEMU runs report it; check.sh reads it). */
static void report_stack(void) {
  char text[40] = "stack_peak_bytes ";
  char digits[12];
  uint32_t v = stack_peak_bytes();
  int n = 0, k = 17;
  do digits[n++] = (char)('0' + v % 10), v /= 10;
  while (v);
  while (n > 0) text[k++] = digits[--n];
  text[k++] = '\n';
  text[k] = 0;
  semihost_write(text);
}

void reset_handler(void) {
  uint32_t *src = &_data_load, *dst = &_data_start;
  volatile uint32_t* cpacr = (volatile uint32_t*)0xE000ED88u;
  uint32_t *s, *sp;
  while (dst < &_data_end) *dst++ = *src++;
  for (dst = &_bss_start; dst < &_bss_end;) *dst++ = 0;
  *cpacr |= 0xFu << 20;
  __asm volatile("dsb\n isb");
  /* Fill the stack below the current stack pointer with the pattern. */
  __asm volatile("mov %0, sp" : "=r"(sp));
  for (s = (uint32_t*)((uintptr_t)&_stack_top - (uintptr_t)&_stack_size); s < sp - 2; ++s) *s = STACK_PATTERN;
  {
    const int status = main();
    report_stack();
    semihost_exit(status);
  }
}
