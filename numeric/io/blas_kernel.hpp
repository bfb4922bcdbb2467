// The same printed numbers on every CPU: OpenBLAS chooses its kernel by the CPU when it loads, and its
// kernels differ in their last bits (on an AVX-512 machine the Cooperlake kernel changed a certified
// enclosure's printed digits, an Ipopt solve's iteration count and a plan's order). A process of scalcal
// therefore runs on OpenBLAS's generic SSE3 kernel, Prescott (every x86-64 CPU has it; BLAS is a small
// part of scalcal's time: `limits --region cap:60` 0.87 s native, 0.82 s Prescott), unless the user's
// OPENBLAS_CORETYPE names another kernel.
#pragma once
#include <string>

namespace scalcal {

inline constexpr const char* kBlasKernel = "Prescott";

// On x86-64 with OPENBLAS_CORETYPE unset or empty: sets it to kBlasKernel and starts the process again (the
// kernel is chosen before main runs) with the same arguments, read from /proc/self/cmdline. Returns
// only when nothing is to be done or the new start failed (then the CPU's kernel stays).
void pin_blas_kernel();

// The kernel OpenBLAS runs ("Prescott", "Cooperlake"), or "" when the BLAS is not OpenBLAS.
std::string blas_kernel();

}  // namespace scalcal
