/* Test side only: raw logs as `scalcal calibrate` reads them (log_reader.h). */
#define _POSIX_C_SOURCE 200809L
#include "log_reader.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

static int split(char* s, char sep, char** fields, int max) {
  int n = 0;
  char* p = s;
  if (sep == ' ') {
    char* tok = strtok(s, " \t\r\n");
    while (tok && n < max) fields[n++] = tok, tok = strtok(0, " \t\r\n");
    return n;
  }
  fields[n++] = p;
  for (; *p && n < max; ++p)
    if (*p == sep) *p = 0, fields[n++] = p + 1;
  return n;
}

static double number(const char* s) {
  char* end;
  double v;
  while (isspace((unsigned char)*s)) ++s;
  if (!strncasecmp(s, "nan", 3)) return NAN;
  v = strtod(s, &end);
  return end == s ? NAN : v;
}

int test_log_read(const char* path, double rate, test_log* log) {
  FILE* f = fopen(path, "r");
  char buf[4096];
  int col[4] = {-1, -1, -1, -1}, text = 0, lineno = 0, cap = 1024, header_done = 0;
  memset(log, 0, sizeof *log);
  if (!f) return fprintf(stderr, "%s: cannot open\n", path), 1;
  log->t = malloc(sizeof(double) * (size_t)cap);
  log->x = malloc(sizeof(double[3]) * (size_t)cap);
  log->line = malloc(sizeof(int) * (size_t)cap);
  while (fgets(buf, sizeof buf, f)) {
    char* fields[64];
    int n, k;
    ++lineno;
    if (buf[0] == '#' || strspn(buf, " \t\r\n") == strlen(buf)) continue;
    if (!header_done) {
      const char* first = buf + strspn(buf, " \t");
      header_done = 1;
      if (isdigit((unsigned char)*first) || *first == '-' || *first == '+' || *first == '.') {
        text = 1;
      } else {
        n = split(buf, ',', fields, 64);
        for (k = 0; k < n; ++k) {
          char name[64];
          size_t len = strcspn(fields[k], "\r\n");
          if (len >= sizeof name) len = sizeof name - 1;
          memcpy(name, fields[k], len), name[len] = 0;
          if (!strcasecmp(name, "ix")) col[1] = k;
          if (!strcasecmp(name, "iy")) col[2] = k;
          if (!strcasecmp(name, "iz")) col[3] = k;
          if (!strcasecmp(name, "t") || !strcasecmp(name, "t_s") || !strcasecmp(name, "time") ||
              !strcasecmp(name, "time_s") || !strcasecmp(name, "timestamp"))
            col[0] = k;
        }
        if (col[1] < 0 || col[2] < 0 || col[3] < 0 || (col[0] < 0 && !(rate > 0)))
          return fprintf(stderr, "%s: needs ix,iy,iz and a time column or a rate\n", path), fclose(f), 1;
        continue;
      }
    }
    n = split(buf, text ? ' ' : ',', fields, 64);
    if (log->rows == cap) {
      cap *= 2;
      log->t = realloc(log->t, sizeof(double) * (size_t)cap);
      log->x = realloc(log->x, sizeof(double[3]) * (size_t)cap);
      log->line = realloc(log->line, sizeof(int) * (size_t)cap);
    }
    if (text) {
      const int off = (rate > 0 && n == 3) ? 0 : 1;
      if (n < 3 + off) return fprintf(stderr, "%s:%d: too few fields\n", path, lineno), fclose(f), 1;
      log->t[log->rows] = off ? number(fields[0]) : 0;
      for (k = 0; k < 3; ++k) log->x[log->rows][k] = number(fields[off + k]);
    } else {
      if (n <= col[1] || n <= col[2] || n <= col[3])
        return fprintf(stderr, "%s:%d: short row\n", path, lineno), fclose(f), 1;
      log->t[log->rows] = col[0] >= 0 ? number(fields[col[0]]) : 0;
      for (k = 0; k < 3; ++k) log->x[log->rows][k] = number(fields[col[k + 1]]);
    }
    if (rate > 0) log->t[log->rows] = (double)log->rows / rate;
    log->line[log->rows] = lineno;
    log->rows++;
  }
  fclose(f);
  return 0;
}

void test_log_free(test_log* log) {
  free(log->t);
  free(log->x);
  free(log->line);
  memset(log, 0, sizeof *log);
}
