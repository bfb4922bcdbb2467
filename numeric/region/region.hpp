// The directions a bench can reach: a union of zones (caps, bands, the six remounted faces, the
// sphere) and finite candidate sets (a jig, a dividing head), parsed from the --region specs.
// Programs and measures for a restricted bench live on a Region; the whole sphere is the default.
#pragma once
#include <string>
#include <vector>

#include "numeric/region/zone.hpp"

namespace scalcal {

// A position counts as inside when it is within this angle of the region (programs are written
// with a few decimals, and a position on a cap's rim must not be refused for rounding).
inline constexpr double kRegionToleranceDeg = 1e-4;

struct Region {
  std::vector<std::string> specs;  // as given, one per --region
  std::vector<Zone> zones;
  std::vector<Vec3> candidates;    // unit vectors

  bool is_sphere() const;
  bool contains(const Vec3& x, double tolerance_deg = kRegionToleranceDeg) const;
  // "cap:30 + faces:10": the union as one line, for reports and JSON.
  std::string text() const;
  // Candidate positions covering the region: the finite candidates, and each zone on rings about its
  // axis spaced step_deg apart in tilt (rims included) and about step_deg apart along each ring.
  std::vector<Vec3> grid(double step_deg) const;
};

Region sphere_region();

// One spec: sphere | cap:DEG[:X,Y,Z] | band:LO:HI[:X,Y,Z] | faces:DEG | candidates:FILE.
// Throws InputError (file "--region", the spec and the reason) for a malformed spec, an angle out of
// range, a zero axis, or a candidate file that cannot be read.
void add_region_spec(Region& region, const std::string& spec);
Region parse_region(const std::vector<std::string>& specs);

}  // namespace scalcal

namespace scalcal {

// Throws InputError (file "--region") when no program on the region can be rank 9, naming the
// parameters that are not identifiable there (e.g. candidates that all lie on one great circle).
// Returns the condition number of the information matrix of the uniform measure on the region's
// grid: large for a small cap, where bias and scale factor are nearly confounded.
double check_region_identifiable(const Region& region);

}  // namespace scalcal
