// libFuzzer target: family parameters (`family NAME --param KEY=VALUE ...`). The first byte picks a
// registered family, each further line is one KEY=VALUE setting; the settings are parsed (symbols,
// exponents and imaginary values checked), and a family whose parameters came out as numbers is
// instantiated and its positions rounded, as `evaluate FAMILY@...` does. Symbolic instances are left
// to the tests: their cost is bounded by the symbol caps, not by the fuzzer's 10 s. Only InputError
// is an expected outcome, as in the CLI.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "numeric/io/input_error.hpp"
#include "symbolic/family.hpp"

namespace {

bool has_symbol(const GiNaC::ex& e) {
  if (GiNaC::is_a<GiNaC::symbol>(e)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i)
    if (has_symbol(e.op(i))) return true;
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1 || size > 512) return 0;
  const auto& families = scalcal::symbolic::families();
  const auto& family = families[data[0] % families.size()];
  std::vector<std::string> settings;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  for (std::string line; std::getline(lines, line);) settings.push_back(line);
  try {
    const scalcal::symbolic::ParamMap params = scalcal::symbolic::parse_params(family, settings);
    for (const auto& [key, value] : params)
      if (has_symbol(value)) return 0;
    (void)family.instance(params);
  } catch (const scalcal::InputError&) {
  }
  return 0;
}
