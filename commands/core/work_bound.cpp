// Work estimates and bounds (work_bound.hpp).
#include "commands/core/work_bound.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <sys/resource.h>
#include <unistd.h>

#include "commands/core/usage_error.hpp"

namespace scalcal::commands {
namespace {

// Bytes of one MPFR number at `digits` decimal digits (the polish works with 25 guard digits): the
// limbs, the struct and the allocator's header.
double mpfr_bytes(int digits) {
  const double bits = (digits + 25) * 3.33;
  return 48 + 8 * std::ceil(bits / 64);
}

std::string amount_of_time(double seconds) {
  char text[64];
  if (seconds < 120)
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  else if (seconds < 2 * 3600)
    std::snprintf(text, sizeof text, "%.0f min", seconds / 60);
  else if (seconds < 2 * 86400)
    std::snprintf(text, sizeof text, "%.0f h", seconds / 3600);
  else
    std::snprintf(text, sizeof text, "%.3g days", seconds / 86400);
  return text;
}

std::string amount_of_memory(double bytes) {
  char text[64];
  if (bytes < 1e9)
    std::snprintf(text, sizeof text, "%.0f MB", bytes / 1e6);
  else
    std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  return text;
}

double cgroup_memory_limit() {
  std::ifstream in("/sys/fs/cgroup/memory.max");  // cgroup v2; "max" when unlimited
  double limit = 0;
  if (in >> limit && limit > 0) return limit;
  return INFINITY;
}

}  // namespace

double available_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  double bytes = pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : INFINITY;
  for (const int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    rlimit r{};
    if (::getrlimit(resource, &r) == 0 && r.rlim_cur != RLIM_INFINITY)
      bytes = std::min(bytes, static_cast<double>(r.rlim_cur));
  }
  return std::min(bytes, cgroup_memory_limit());
}

void check_work(const std::string& what, const WorkEstimate& e, const std::string& advice) {
  if (e.cpu_seconds > kMaxCpuSeconds)
    throw UsageError(what + " would take about " + amount_of_time(e.cpu_seconds) + " of CPU (estimate); the bound is " +
                     amount_of_time(kMaxCpuSeconds) + ": " + advice);
  const double allowed = available_memory_bytes();
  if (e.bytes > allowed)
    throw UsageError(what + " would need about " + amount_of_memory(e.bytes) +
                     " of memory (estimate); this process may use " + amount_of_memory(allowed) + ": " + advice);
}

// Measured (one thread, user CPU, issue 50): per program of the paper's model at N = 12, D 0.13 us (the
// determinant only, in batches), A 0.47 us, S 0.67 us, E 5.2 us (9 x 9 eigenvalues); each position adds
// 7.5 ns (N = 1000: D 7.5 us). Another model's programs are scored one by one: 13 us for cubic12's D at
// N = 12. A position's cost grows as the parameters squared (moments), a program's as their cube.
WorkEstimate random_search_work(long long count, int positions, int parameters, double scoring_seconds) {
  const double p = parameters / 9.0;
  // The criteria's prices (their types' scoring_seconds) were measured on a Zen 4 (issue 50's prices were 1.6-3.4x
  // over there; tests/robustness/work_estimates_test.cpp wants every command within 3x on every machine it runs on,
  // slower ones too): 0.6 of those prices.
  const double price = parameters != 9 ? 3.6e-6 * p * p * p : scoring_seconds;
  const double per_program = positions * 4.8e-9 * p * p + price;
  return {static_cast<double>(count) * per_program, 2e7 + 64.0 * positions};
}

// Measured at 50 digits: 1.8 s per Newton iteration at N = 50, 9.7 s at N = 100 (central differences,
// O(N^2), then the decomposition, O(N^3)); 2x per iteration at 200 digits; 3.5 kB per N^2 of memory
// (about 44 MPFR numbers per N^2). Five iterations are typical.
WorkEstimate polish_work(int positions, int digits) {
  const double n = positions, d = digits;
  // Issue 50: from a random program (the damped steps' extra residuals) 0.55 s an iteration at N = 20 and
  // 1.1 s at 30, measured: the linear term.
  const double per_iteration =
      (1.5e-2 * n + 4.5e-4 * n * n + 5.2e-6 * n * n * n) * (0.5 + d / 100 + (d / 400) * (d / 400));
  return {5 * per_iteration, 2e7 + 44 * n * n * mpfr_bytes(digits)};
}

// Measured at 60 digits on rotation programs: 65 s and 2.9 GB at N = 3000, 11.5 GB at N = 6000.
WorkEstimate certify_work(int positions, int digits) {
  const double n = positions / 3000.0, scale = mpfr_bytes(digits) / mpfr_bytes(60);
  return {65 * n * n * n * scale, 2e7 + 2.9e9 * n * n * scale};
}

// Measured: 3 s and 160 MB at N = 1000, 15 s and 580 MB at N = 2000; issue 50, user CPU: 0.64 s at
// N = 400, 5.0 s at 1000 (N^2.25).
WorkEstimate augment_work(int positions) {
  const double n = positions / 1000.0;
  return {5 * std::pow(n, 2.25), 2e7 + 1.4e8 * n * n};
}

// Measured (user CPU): 0.31 s at N = 1000, 1.30 s at 2000, 6.2 s and 144 MB at 4000 on gimbal:x,y (2
// settings a position); 1.85 s at N = 500, 6.2 s at 1000, 25.5 s at 2000 on gimbal:x,y,z (24 settings:
// 12 samples of the outer axis). The pairs' distances over their settings, then the paths: N^2 (1.1e-8
// c^2 + 2.8e-7) s; the distances' table is 8 N^2 bytes (100000 positions: 80 GB).
WorkEstimate plan_work(int positions, double settings) {
  const double n = positions;
  return {n * n * (1.1e-8 * settings * settings + 2.8e-7), 2e7 + 8.0 * n * n + 200 * n * settings};
}

// Measured (user CPU, per calibration: trials x moduli): 6.8e-4 s at N = 200 with 5 samples, 1.5e-3 s
// with 50; 2.6e-3 s at N = 1000 with 1; 2.2e-3 s at N = 100 with 200: 9.2e-8 s a sample (drawn and
// averaged) and 2.9e-6 s a position (the fit), the fit growing with the parameters squared.
WorkEstimate monte_carlo_work(long long trials, int positions, long long samples, int parameters) {
  const double p = parameters / 9.0, n = positions;
  const double per_trial = 1e-7 * n * static_cast<double>(samples) + 3e-6 * n * p * p;
  return {static_cast<double>(trials) * per_trial, 2e7 + 8.0 * n * (3 + 3.0 * static_cast<double>(samples))};
}

// Measured (user CPU, gnuplot included): 0.2 s for classic18, 0.74 s for 2000 positions and 3.5 s for
// 10000 (gnuplot draws each point and its number three times: 2.5e-4 s a position); the shaded disks
// add 0.5 s, and 1.2e-9 s per pixel and candidate (3000 candidates: 0.4 s). 100000 positions: 22.5 s.
WorkEstimate plot_work(int positions, int zones, int candidates, bool shaded_disks) {
  const double pixels = shaded_disks ? 2.0 * 241 * 241 : 0;
  const double cpu = 0.2 + 2.5e-4 * positions + (shaded_disks ? 0.5 : 0) + 1.2e-9 * pixels * (zones + candidates);
  return {cpu, 2e7 + 400.0 * positions + 60 * pixels};
}

}  // namespace scalcal::commands
