// Work estimates and bounds (work_bound.hpp).
#include "commands/work_bound.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include <sys/resource.h>
#include <unistd.h>

#include "commands/usage_error.hpp"

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

// Measured: 6.6 M programs/s/core for D at N = 18 and 8.5 ns per position at N = 1000; E's 9 x 9
// eigenvalues cost 5.3 us a program. Here every criterion is charged E's price, and a model's cost
// grows as its parameters squared (moments) and cubed (the factorisation).
WorkEstimate random_search_work(long long count, int positions, int parameters) {
  const double p = parameters / 9.0;
  const double per_program = positions * 1e-8 * p * p + 6e-6 * p * p * p;
  return {static_cast<double>(count) * per_program, 2e7 + 64.0 * positions};
}

// Measured at 50 digits: 1.8 s per Newton iteration at N = 50, 9.7 s at N = 100 (central differences,
// O(N^2), then the decomposition, O(N^3)); 2x per iteration at 200 digits; 3.5 kB per N^2 of memory
// (about 44 MPFR numbers per N^2). Five iterations are typical.
WorkEstimate polish_work(int positions, int digits) {
  const double n = positions, d = digits;
  const double per_iteration = (4.5e-4 * n * n + 5.2e-6 * n * n * n) * (0.5 + d / 100 + (d / 400) * (d / 400));
  return {5 * per_iteration, 2e7 + 44 * n * n * mpfr_bytes(digits)};
}

// Measured at 60 digits on rotation programs: 65 s and 2.9 GB at N = 3000, 11.5 GB at N = 6000.
WorkEstimate certify_work(int positions, int digits) {
  const double n = positions / 3000.0, scale = mpfr_bytes(digits) / mpfr_bytes(60);
  return {65 * n * n * n * scale, 2e7 + 2.9e9 * n * n * scale};
}

// Measured: 3 s and 160 MB at N = 1000, 15 s and 580 MB at N = 2000.
WorkEstimate augment_work(int positions) {
  const double n = positions / 1000.0;
  return {3 * std::pow(n, 2.5), 2e7 + 1.4e8 * n * n};
}

}  // namespace scalcal::commands
