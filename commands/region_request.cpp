// Regions of requests (region_request.hpp).
#include "commands/region_request.hpp"

#include <cstdio>

#include "numeric/criteria/identifiability.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal::commands {
namespace {

std::string short_number(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

}  // namespace

bool is_sphere(const std::vector<std::string>& specs) {
  return specs.empty() || (specs.size() == 1 && specs[0] == "sphere");
}

Region resolve_region(const std::vector<std::string>& specs, Warnings& warnings) {
  Region region = parse_region(specs);
  const double condition = check_region_identifiable(region);
  if (condition > kBeyondDouble)
    throw InputError("--region", 0,
                     "'" + region.text() + "': even the uniform measure has condition number " +
                         short_number(condition) +
                         ", beyond what double precision resolves (1e14): bias and scale factor are confounded "
                         "there (a cap narrower than about 4 degrees)");
  if (condition > kIllConditioned)
    warnings.push_back({"", "on " + region.text() + " even the uniform measure has condition number " +
                                short_number(condition) + " (bias and scale factor are nearly confounded there)"});
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

void refuse_outside(const std::string& name, const Program& program, const Region& region) {
  std::vector<int> outside;
  for (int i = 0; i < program.size(); ++i)
    if (!region.contains(program.positions[static_cast<std::size_t>(i)])) outside.push_back(i);
  if (outside.empty()) return;
  std::string list;
  for (std::size_t k = 0; k < outside.size() && k < 10; ++k) {
    const int i = outside[k];
    list += (k ? ", " : "") + std::to_string(i + 1);
    if (!region.zones.empty()) {
      char tilt[32];
      std::snprintf(tilt, sizeof tilt, "%.4g",
                    region.zones.front().tilt_deg(program.positions[static_cast<std::size_t>(i)]));
      list += std::string(" (tilt ") + tilt + " deg)";
    }
  }
  if (outside.size() > 10) list += ", ...";
  throw InputError(name, 0,
                   std::to_string(outside.size()) + " of " + std::to_string(program.size()) +
                       " positions are outside the region " + region.text() + ": position " + list);
}

}  // namespace scalcal::commands
