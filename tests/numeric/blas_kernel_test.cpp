// The BLAS kernel every test executable runs on (tests/common/blas_kernel_pin.cpp pins it as the CLI does).
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "numeric/io/blas_kernel.hpp"

namespace {

// Prescott unless the environment names another kernel: an empty OPENBLAS_CORETYPE is no choice (OpenBLAS
// itself then picks the CPU's kernel, Cooperlake on an AVX-512 machine, so the pin must set it). ctest runs this
// once more with the variable set empty (numeric.blas_kernel_empty).
TEST(BlasKernel, PinnedUnlessTheUserNamesOne) {
  const char* chosen = std::getenv("OPENBLAS_CORETYPE");
  ASSERT_NE(chosen, nullptr) << "the pin sets OPENBLAS_CORETYPE before main";
  if (*chosen != '\0' && std::string(chosen) != scalcal::kBlasKernel)
    GTEST_SKIP() << "OPENBLAS_CORETYPE=" << chosen << " chosen by the user";
  EXPECT_STREQ(chosen, scalcal::kBlasKernel);
  const std::string kernel = scalcal::blas_kernel();
  if (kernel.empty()) GTEST_SKIP() << "the BLAS is not OpenBLAS";
  EXPECT_EQ(kernel, scalcal::kBlasKernel);
}

}  // namespace
