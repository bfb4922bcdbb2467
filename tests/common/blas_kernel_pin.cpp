// Every test executable runs on the kernel the CLI pins (numeric/io/blas_kernel.hpp), so that a test of
// the library in-process sees the numbers a user of the CLI or the Python module sees on any CPU.
#include "numeric/io/blas_kernel.hpp"

namespace {
const bool pinned = (scalcal::pin_blas_kernel(), true);
}  // namespace
