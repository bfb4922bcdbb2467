// Two pieces of per-call bookkeeping in Debian's solvers that scalcal never reads, replaced. Each is
// called across a shared-library boundary (through the PLT), so a definition exported from the
// executable (every one that links scalcal exports these: ld sees them defined in the libraries too)
// takes the library's place. Factors, solutions, iterates and every result are unchanged: reproduce's
// CSVs were byte for byte the same with and without.
// - MUMPS 5.5 computes, at the end of every factorisation and every solve, how much disk a saved
//   instance would take, by walking its whole structure with Fortran string compares: 15-21 % of the CPU
//   of Ipopt's solves here (E at N = 9: 38 -> 29-36 ms a start; cap:10's N scan 3.3-3.5 -> 2.4-2.8 s).
//   Ipopt never saves an instance; MUMPS only stores the two sizes (KEEP8(55..58), RINFO(7..8),
//   RINFOG(17..18)). The replacement reports zero.
// - Ipopt 3.11 times each of its tasks with getrusage, whatever its options say: 9.9 million calls in
//   one reproduce, about 8 % of its CPU. scalcal reads none of Ipopt's timings and sets no max_cpu_time,
//   so Ipopt's CPU and system clocks read 0 here. (Intercepting getrusage itself would change a C
//   library function for the whole process; these two are Ipopt's own.)
#include "numeric/synthesis/solver_bookkeeping.hpp"

#include <dlfcn.h>

#include <cstdint>

#include <IpUtils.hpp>

// The Fortran module procedure's symbol (gfortran's mangling), taken by an asm label: an identifier
// with a leading double underscore is reserved in C++.
extern "C" __attribute__((visibility("default"), used)) void scalcal_mumps_compute_memory_save(
    void* instance, std::int64_t* file_size,
    std::int64_t* structure_size) __asm__("__dmumps_save_restore_MOD_dmumps_compute_memory_save");

extern "C" void scalcal_mumps_compute_memory_save(void*, std::int64_t* file_size, std::int64_t* structure_size) {
  *file_size = 0;
  *structure_size = 0;
}

namespace Ipopt {

__attribute__((visibility("default"))) Number CpuTime() { return 0; }
__attribute__((visibility("default"))) Number SysTime() { return 0; }

}  // namespace Ipopt

namespace scalcal {

bool solver_bookkeeping_replaced() {
  return dlsym(RTLD_DEFAULT, "__dmumps_save_restore_MOD_dmumps_compute_memory_save") ==
             reinterpret_cast<void*>(&scalcal_mumps_compute_memory_save) &&
         dlsym(RTLD_DEFAULT, "_ZN5Ipopt7CpuTimeEv") == reinterpret_cast<void*>(&Ipopt::CpuTime) &&
         dlsym(RTLD_DEFAULT, "_ZN5Ipopt7SysTimeEv") == reinterpret_cast<void*>(&Ipopt::SysTime);
}

}  // namespace scalcal
