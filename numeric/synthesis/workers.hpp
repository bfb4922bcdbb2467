// Local optimisations in forked worker processes: Ipopt's linear solver (sequential MUMPS) is not
// thread-safe. Tasks are dealt round-robin and results stored by index, so nothing depends on
// scheduling; each result crosses the pipe as one typed record.
#pragma once
#include <functional>
#include <vector>

#include "numeric/synthesis/local_result.hpp"

namespace scalcal {

// task(k) for k < tasks, in min(workers, tasks) child processes (at least one: the caller's process
// never initialises MUMPS, whose state a later fork would otherwise inherit). Every program returned
// has `positions` positions. Throws std::runtime_error when a worker fails.
std::vector<LocalResult> run_in_workers(int tasks, int workers, int positions,
                                        const std::function<LocalResult(int)>& task,
                                        const std::function<void(int done, int total)>& progress = {});

// f() in one child process (for work that initialises Ipopt, whose MUMPS state a later fork must
// not inherit); its `size` doubles come back through the same pipe as a program's coordinates.
std::vector<double> run_in_child(int size, const std::function<std::vector<double>()>& f);

}  // namespace scalcal
