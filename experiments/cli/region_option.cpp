#include "experiments/cli/region_option.hpp"

#include <cstdio>
#include <iostream>

#include "experiments/cli/options.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::cli {

void add_region_option(CLI::App& app, std::vector<std::string>& specs) {
  add_repeatable(app, "--region", specs, "SPEC",
                 {"directions the bench reaches; repeat for a union: sphere, cap:DEG[:X,Y,Z], band:LO:HI[:X,Y,Z], "
                  "faces:DEG, candidates:FILE",
                  "degrees", "sphere"});
}

Region resolve_region(const std::vector<std::string>& specs, const std::string& command) {
  Region region = parse_region(specs);
  const double condition = check_region_identifiable(region);
  if (condition > kBeyondDouble) {
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", condition);
    throw InputError("--region", 0,
                     "'" + region.text() + "': even the uniform measure has condition number " + text +
                         ", beyond what double precision resolves (1e14): bias and scale factor are confounded "
                         "there (a cap narrower than about 4 degrees)");
  }
  if (condition > kIllConditioned) {
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", condition);
    std::cerr << "scalcal " << command << ": warning: on " << region.text()
              << " even the uniform measure has condition number " << text
              << " (bias and scale factor are nearly confounded there)\n";
  }
  return region;
}

std::vector<ExtraColumn> region_columns(const Region& region, const Program& program) {
  if (region.zones.size() != 1 || !region.candidates.empty() || region.is_sphere()) return {};
  const Zone& zone = region.zones.front();
  ExtraColumn tilt{"tilt_deg", {}}, azimuth{"azimuth_deg", {}};
  for (const Vec3& x : program.positions) {
    tilt.values.push_back(zone.tilt_deg(x));
    azimuth.values.push_back(azimuth_deg(zone, x));
  }
  return {tilt, azimuth};
}

}  // namespace scalcal::cli
