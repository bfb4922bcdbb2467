// A request to stop long work early: Python's Ctrl-C. A front end sets it from another thread; the
// library's long loops look at it between units of work (a batch of random programs, a Newton step or
// Jacobian column, a start, a task, a trial) and stop by throwing Interrupted, or return early from a
// worker thread and let the thread that joins them throw. The CLI never sets it (Ctrl-C ends the
// process).
#pragma once
#include <atomic>
#include <stdexcept>

namespace scalcal {

class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted") {}
};

// The process-wide request (one per process: inline, so every unit shares it).
inline std::atomic<bool>& interrupt_request() {
  static std::atomic<bool> requested{false};
  return requested;
}

inline bool interrupt_requested() { return interrupt_request().load(std::memory_order_relaxed); }

// Throws Interrupted when a stop was requested.
inline void check_interrupt() {
  if (interrupt_requested()) throw Interrupted();
}

}  // namespace scalcal
