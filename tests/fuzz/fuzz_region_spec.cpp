// libFuzzer target: --region specs (issue 11), one per line of the input, as a repeated option
// gives them: parsed, then the region's text, membership, grid, meridians and sampler are used.
// candidates:FILE specs are skipped (they are the program CSV reader, fuzzed on its own, and a
// path could name a FIFO that never answers). Only InputError is an expected outcome, as in the CLI.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "numeric/io/input_error.hpp"
#include "numeric/region/region.hpp"
#include "numeric/region/region_sampler.hpp"
#include "numeric/synthesis/random_search_kernel.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 1024) return 0;
  std::vector<std::string> specs;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data), size));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("candidates", 0) == 0) return 0;
    specs.push_back(line);
  }
  try {
    const scalcal::Region region = scalcal::parse_region(specs);
    (void)region.text();
    (void)region.contains(scalcal::Vec3(0, 0, 1));
    (void)region.contains(scalcal::Vec3(0.6, 0, -0.8));
    const auto grid = region.grid(15.0);
    for (const auto& zone : region.zones) (void)region.meridians(zone);
    (void)region.measure_grid(20.0);
    if (!region.zones.empty()) {
      double x[16], y[16], z[16];
      scalcal::Xoshiro256x4 rng(1);
      scalcal::region_sampler(region)(rng, 9, x, y, z);
    }
  } catch (const scalcal::InputError&) {
  }
  return 0;
}
