// libFuzzer target: catalogue names (rotation-K-pDEG, octahedral-A-E-D, random-N-sSEED, ...), the
// other way a program reaches every subcommand. Names only: no file is opened. Only InputError is
// an expected outcome, as in the CLI.
#include <cstddef>
#include <cstdint>
#include <string>

#include "numeric/io/input_error.hpp"
#include "numeric/program/catalogue.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 256) return 0;  // names are short; longer input only slows the search
  try {
    (void)scalcal::named_program(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const scalcal::InputError&) {
  }
  return 0;
}
