// Work bounds that scale with the work: a request's CPU time and memory are estimated from its size
// before it starts, and a request estimated beyond the bounds is refused (exit 2) with the estimate in
// the message, so that no short command line asks for days of CPU or more memory than the machine
// has. The estimates are fitted to measurements on the 2-core development machine (docs/reliability.md)
// and err on the high side; they decide only whether to start, never what is computed.
#pragma once
#include <string>
#include <string_view>

namespace scalcal::commands {

struct WorkEstimate {
  double cpu_seconds = 0;
  double bytes = 0;
};

// One day of CPU: far beyond any documented use, far below the hangs a typo can ask for.
inline constexpr double kMaxCpuSeconds = 24 * 3600.0;

// The memory this process may use: physical memory, or less when an address-space limit (ulimit -v)
// or a cgroup limit is set.
double available_memory_bytes();

// Throws UsageError "<what> would need about 3.1 days of CPU (estimate); the bound is 1 day: <advice>"
// (or "about 12 GB of memory; this machine allows 8 GB") when the estimate is beyond a bound.
void check_work(const std::string& what, const WorkEstimate& estimate, const std::string& advice);

// The estimates, one per kind of work whose cost grows faster than its input.
// random: `count` programs of N positions for a model with `parameters` parameters, by a criterion whose price of
// one program of the paper's model is `scoring_seconds` (criterion_scoring_seconds, numeric/criteria/registry.hpp).
WorkEstimate random_search_work(long long count, int positions, int parameters, double scoring_seconds);
// polish (and optimize --digits): Newton in MPFR at `digits` digits on N positions (a dense Jacobian
// of ~3N x 3N numbers and its orthogonal decomposition).
WorkEstimate polish_work(int positions, int digits);
// certify: interval Hessians of ~3N x 3N at `digits` digits.
WorkEstimate certify_work(int positions, int digits);
// augment: the joint polish of N given plus added positions in double (a dense ~3N x 3N step).
WorkEstimate augment_work(int positions);
// plan: the run order of N positions with `settings` bench settings each on average (the distance of
// every pair of positions over every pair of their settings, nearest-neighbour paths, 2-opt).
WorkEstimate plan_work(int positions, double settings);
// simulate's Monte-Carlo: `trials` calibrations of N positions with `samples` samples each for a model
// of `parameters` parameters.
WorkEstimate monte_carlo_work(long long trials, int positions, long long samples, int parameters);
// plot: the region's pixels tested against its zones and candidates, and the program's positions.
WorkEstimate plot_work(int positions, int zones, int candidates, bool shaded_disks);

}  // namespace scalcal::commands
