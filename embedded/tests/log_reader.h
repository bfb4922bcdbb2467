/* Test side only (host): a raw log read into memory as `scalcal calibrate` reads it: whitespace text
 * `t ix iy iz` (or `ix iy iz` with a rate), or CSV with a header naming ix, iy, iz and a time column
 * (t, t_s, time, time_s, timestamp); with rate > 0 the time of row k is k / rate. */
#ifndef SCALCAL_TEST_LOG_READER_H
#define SCALCAL_TEST_LOG_READER_H

typedef struct {
  int rows;
  double* t;
  double (*x)[3];
  int* line; /* 1-based line of each row */
} test_log;

/* 0 on success; prints the reason and returns 1 otherwise. */
int test_log_read(const char* path, double rate, test_log* log);
void test_log_free(test_log* log);

#endif
