// Errors of the machine, not of the request or its data: a worker process or thread that could not
// be started, memory the system refused. The CLI prints the reason and exits 1 (not "internal error":
// nothing is wrong with scalcal or the input, and the same request may succeed with more resources).
#pragma once
#include <stdexcept>

namespace scalcal {

class ResourceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace scalcal
