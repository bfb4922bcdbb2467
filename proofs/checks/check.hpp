// A tiny harness for the proof checks: each claim is one CHECK; the program exits 1 if any fails,
// so CTest reports the theorem as not verified.
#pragma once
#include <cstdlib>
#include <iostream>

namespace scalcal::proofs {
inline int& failures() {
  static int n = 0;
  return n;
}
inline void check(bool ok, const char* claim) {
  std::cout << (ok ? "  ok    " : "  FAIL  ") << claim << "\n";
  if (!ok) ++failures();
}
inline int finish() {
  std::cout << (failures() ? "NOT VERIFIED\n" : "verified\n");
  return failures() ? 1 : 0;
}
}  // namespace scalcal::proofs
