// libFuzzer target: program names with the symbolic families registered, as the CLI has them
// (jig:cube@orientation=aa:1,2,3,40, octahedral@axes=2, dodecahedral-12, ...), on top of the paper's
// catalogue names of fuzz_catalogue_name. Names only: no file is opened. Only InputError is an
// expected outcome, as in the CLI.
#include <cstddef>
#include <cstdint>
#include <string>

#include "numeric/io/input_error.hpp"
#include "numeric/program/catalogue.hpp"
#include "symbolic/family.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool registered = (scalcal::symbolic::register_family_programs(), true);
  (void)registered;
  if (size > 256) return 0;  // names are short; longer input only slows the search
  try {
    (void)scalcal::named_program(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const scalcal::InputError&) {
  }
  return 0;
}
