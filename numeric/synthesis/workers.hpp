// Local optimisations on several cores: in threads of this process for work that never calls Ipopt
// (Newton, L-BFGS, the exchange), in forked worker processes for work that does (Ipopt's linear
// solver, sequential MUMPS, is not thread-safe). Results are stored by task index, so nothing
// depends on scheduling; from a worker process each result crosses the pipe as one typed record.
#pragma once
#include <functional>
#include <vector>

#include "numeric/synthesis/local_result.hpp"

namespace scalcal {

// task(k) for k < tasks, in min(workers, tasks) child processes (at least one: the caller's process
// never initialises MUMPS, whose state a later fork would otherwise inherit), each taking the next
// task from a shared counter when it is free. Every program returned
// has `positions` positions. Throws std::runtime_error when a worker fails.
std::vector<LocalResult> run_in_workers(int tasks, int workers, int positions,
                                        const std::function<LocalResult(int)>& task,
                                        const std::function<void(int done, int total)>& progress = {});

// task(k) for k < tasks on min(threads, tasks) threads of this process (the caller's thread is one
// of them), taking tasks from a shared counter; progress is called from one thread at a time. An
// exception thrown by a task is rethrown here once every thread has stopped.
std::vector<LocalResult> run_in_threads(int tasks, int threads, const std::function<LocalResult(int)>& task,
                                        const std::function<void(int done, int total)>& progress = {});

// task(k) for k < tasks in worker processes, as run_in_workers, for results of `size` doubles each
// (shorter results are padded with zeros, longer ones cut).
std::vector<std::vector<double>> run_values_in_workers(int tasks, int workers, int size,
                                                       const std::function<std::vector<double>(int)>& task,
                                                       const std::function<void(int done, int total)>& progress = {});

// f() in one child process (for work that initialises Ipopt, whose MUMPS state a later fork must
// not inherit); its `size` doubles come back through the same pipe as a program's coordinates.
std::vector<double> run_in_child(int size, const std::function<std::vector<double>()>& f);

}  // namespace scalcal
