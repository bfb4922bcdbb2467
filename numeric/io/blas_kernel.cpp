// Pinning OpenBLAS's kernel (blas_kernel.hpp).
#include "numeric/io/blas_kernel.hpp"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>

#include <dlfcn.h>
#include <unistd.h>

namespace scalcal {

void pin_blas_kernel() {
#if defined(__x86_64__)
  // An empty value counts as unset, as OpenBLAS itself takes it (it then picks the CPU's kernel).
  const char* chosen = std::getenv("OPENBLAS_CORETYPE");
  if (chosen != nullptr && *chosen != '\0') return;
  if (setenv("OPENBLAS_CORETYPE", kBlasKernel, 1) != 0) return;
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::string> args;
  for (std::size_t at = 0; at < all.size();) {
    const std::size_t end = all.find('\0', at);
    args.push_back(all.substr(at, end == std::string::npos ? std::string::npos : end - at));
    if (end == std::string::npos) break;
    at = end + 1;
  }
  if (args.empty()) return;
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  execv("/proc/self/exe", argv.data());  // returns only on failure: run on with the CPU's kernel
#endif
}

std::string blas_kernel() {
  using CoreName = char* (*)();
  const auto f = reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
  return f ? std::string(f()) : std::string();
}

}  // namespace scalcal
