// Several region limits at once, in worker processes: each limit is computed alone, as
// region_limit() computes it, so the results are the same as one by one, in any order of completion.
// Processes, not threads: the exact weights run Ipopt, whose linear solver (sequential MUMPS) is not
// thread-safe. fig12's 84 limits and `scalcal limits`' four took one core each.
#pragma once
#include <functional>
#include <vector>

#include "numeric/region/region_limit.hpp"

namespace scalcal {

struct RegionLimitTask {
  CriterionKind criterion;
  Region region;
};

// The limit of every task, in task order, on min(workers, tasks) processes (workers <= 1: here, in
// order). progress(done, total) is called as results arrive.
std::vector<RegionLimit> region_limits(const std::vector<RegionLimitTask>& tasks, const RegionLimitOptions& options,
                                       int workers, const std::function<void(int done, int total)>& progress = {});

}  // namespace scalcal
