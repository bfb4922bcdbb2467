// One lock for every call into the library from Python (module.cpp's commands, stream.cpp's streams).
#pragma once
#include <mutex>

#include <pybind11/pybind11.h>

namespace scalcal::python {

// One call into the library at a time: GiNaC/CLN (program names, families) and Ipopt/MUMPS are not
// thread-safe, and two Python threads calling at once crashed the interpreter. The lock is taken
// with the GIL released, so a thread waiting for it never holds up the one that has it.
inline std::mutex& library_mutex() {
  static std::mutex m;
  return m;
}

class LibraryLock {
 public:
  LibraryLock() {
    pybind11::gil_scoped_release free;
    library_mutex().lock();
  }
  ~LibraryLock() { library_mutex().unlock(); }
  LibraryLock(const LibraryLock&) = delete;
  LibraryLock& operator=(const LibraryLock&) = delete;
};

}  // namespace scalcal::python
