/* Test side only: the whole streaming path on one real log (data/xsens_acc.txt, read by
 * semihosting): every sample through the detector, the fit, the guidance and a flash record read
 * back, each result printed as the exact bits of its value. Built for the Cortex-M4F (run under
 * QEMU) and for the host (host_io.c): check.sh requires the two outputs to be byte for byte the
 * same. The numbers are parsed here (Clinger's fast path: integer mantissa, one correctly rounded
 * multiplication or division by an exact power of ten), the same way on both. */
#include <stdint.h>
#include <string.h>

#include "scalcal/detector.h"
#include "scalcal/fit.h"
#include "scalcal/guidance.h"
#include "scalcal/record.h"
#include "semihost.h"

#ifndef LOG_PATH
#define LOG_PATH "xsens_acc.txt"
#endif

static scalcal_pose storage[SCALCAL_MAX_POSES];
static scalcal_detector det;
static char buffer[4096 + 256];

static const double kPow10[23] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                  1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

/* One decimal number at *p; 0 when it is not one the fast path reads exactly. */
static int parse_number(const char** p, double* out) {
  const char* s = *p;
  uint64_t mantissa = 0;
  int negative = 0, exponent = 0, digits = 0, e = 0, eneg = 0;
  if (*s == '-' || *s == '+') negative = *s++ == '-';
  for (; *s >= '0' && *s <= '9'; ++s, ++digits) mantissa = mantissa * 10 + (uint64_t)(*s - '0');
  if (*s == '.')
    for (++s; *s >= '0' && *s <= '9'; ++s, ++digits, --exponent) mantissa = mantissa * 10 + (uint64_t)(*s - '0');
  if (*s == 'e' || *s == 'E') {
    ++s;
    if (*s == '-' || *s == '+') eneg = *s++ == '-';
    for (; *s >= '0' && *s <= '9'; ++s) e = e * 10 + (*s - '0');
    exponent += eneg ? -e : e;
  }
  *p = s;
  if (digits == 0 || digits > 19 || mantissa > (1ull << 53) || exponent > 22 || exponent < -22) return 0;
  *out = exponent >= 0 ? (double)mantissa * kPow10[exponent] : (double)mantissa / kPow10[-exponent];
  if (negative) *out = -*out;
  return 1;
}

static void put_hex(uint64_t v, int digits) {
  static const char hex[] = "0123456789abcdef";
  char text[20];
  int k;
  text[0] = ' ';
  for (k = 0; k < digits; ++k) text[1 + k] = hex[(v >> (4 * (digits - 1 - k))) & 15];
  text[1 + digits] = 0;
  semihost_write(text);
}

static void put_uint(const char* key, uint32_t v) {
  char text[16];
  int n = 0, k;
  semihost_write(key);
  do text[n++] = (char)('0' + v % 10), v /= 10;
  while (v);
  semihost_write(" ");
  for (k = n - 1; k >= 0; --k) {
    char c[2] = {text[k], 0};
    semihost_write(c);
  }
  semihost_write("\n");
}

/* key and the exact bits of n values */
static void put_reals(const char* key, const scalcal_real* v, int n) {
  int k;
  semihost_write(key);
  for (k = 0; k < n; ++k) {
    uint64_t bits = 0;
    memcpy(&bits, &v[k], sizeof v[k]);
    put_hex(bits, (int)(2 * sizeof v[k]));
  }
  semihost_write("\n");
}

/* Reads the log (t ix iy iz per line) and pushes every sample; returns the rows read, or -1. */
static long feed(scalcal_pose_set* set) {
  const int handle = semihost_open(LOG_PATH);
  long have = 0, rows = 0, got;
  if (handle < 0) return -1;
  while ((got = semihost_read(handle, buffer + have, 4096 - have)) > 0 || have > 0) {
    const char* p = buffer;
    const char* end;
    have += got > 0 ? got : 0;
    end = buffer + have;
    for (;;) {
      const char* line_end = memchr(p, '\n', (size_t)(end - p));
      double v[4];
      int k;
      if (!line_end) {
        if (got > 0) break;
        line_end = end; /* the last line without a newline */
        if (p == end) break;
      }
      for (k = 0; k < 4; ++k) {
        while (p < line_end && (*p == ' ' || *p == '\t' || *p == '\r')) ++p;
        if (!parse_number(&p, &v[k])) return -1;
      }
      {
        const scalcal_real x[3] = {(scalcal_real)v[1], (scalcal_real)v[2], (scalcal_real)v[3]};
        scalcal_detector_push(&det, set, x);
      }
      ++rows;
      p = line_end < end ? line_end + 1 : end;
    }
    have = end - p;
    memmove(buffer, p, (size_t)have);
    if (got <= 0) break;
  }
  semihost_close(handle);
  return rows;
}

int main(void) {
  scalcal_pose_set set;
  scalcal_detector_options dop;
  scalcal_fit_options fop;
  scalcal_calibration cal, back;
  scalcal_fit_report report;
  scalcal_program_quality quality;
  scalcal_status status;
  uint8_t record[SCALCAL_RECORD_SIZE];
  uint32_t best, c;
  scalcal_real after;
  long rows;
  semihost_write(sizeof(scalcal_real) == 8 ? "precision double\n" : "precision float\n");
  scalcal_pose_set_init(&set, storage, SCALCAL_MAX_POSES);
  scalcal_detector_options_default(&dop, 100);
  if (scalcal_detector_init(&det, &dop) != SCALCAL_OK) return 2;
  rows = feed(&set);
  if (rows < 0) {
    semihost_write("cannot read " LOG_PATH "\n");
    return 2;
  }
  scalcal_detector_finish(&det, &set);
  put_uint("rows", (uint32_t)rows);
  put_uint("poses", set.count);
  put_reals("floor", &det.floor, 1);
  scalcal_fit_options_default(&fop);
  fop.magnitude = (scalcal_real)9.81744;
  status = scalcal_fit(&set, &fop, &cal, &report);
  put_uint("status", (uint32_t)status);
  put_uint("model", (uint32_t)report.model);
  put_uint("iterations", (uint32_t)report.iterations);
  if (status != SCALCAL_OK) return 1;
  put_reals("offset", cal.offset, 3);
  put_reals("matrix", &cal.matrix[0][0], 9);
  put_reals("scale_deviation", cal.scale_deviation, 3);
  put_reals("nonorthogonality", cal.nonorthogonality, 3);
  put_reals("bias_std", cal.bias_std, 3);
  put_reals("scale_deviation_std", cal.scale_deviation_std, 3);
  put_reals("nonorthogonality_std", cal.nonorthogonality_std, 3);
  put_reals("noise", &cal.noise, 1);
  put_reals("residual_rms", &cal.residual_rms, 1);
  scalcal_program_quality_of(&set, &cal, report.model, &quality);
  put_reals("efficiency", quality.efficiency, 4);
  for (c = 0; c < 4; ++c) {
    scalcal_next_pose(&set, &cal, report.model, (scalcal_criterion)c, scalcal_candidates26, 26, &best, &after);
    put_uint("next_pose", best);
    put_reals("after", &after, 1);
  }
  scalcal_record_write(&cal, 1, record);
  put_uint("record_crc", (uint32_t)record[124] | (uint32_t)record[125] << 8 | (uint32_t)record[126] << 16 |
                             (uint32_t)record[127] << 24);
  put_uint("record_read", (uint32_t)scalcal_record_read(record, &back, 0));
  return 0;
}
