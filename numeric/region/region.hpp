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
  std::vector<Vec3> candidates;  // unit vectors
  double inset_deg = 0;          // the zones' boundaries moved inwards by this (inset_region)

  bool is_sphere() const;
  bool contains(const Vec3& x, double tolerance_deg = kRegionToleranceDeg) const;
  // "cap:30 + faces:10": the union as one line, for reports and JSON.
  std::string text() const;
  // Candidate positions covering the region: the finite candidates, and each zone on rings about its
  // axis spaced step_deg apart in tilt (rims included) and about step_deg apart along each ring.
  std::vector<Vec3> grid(double step_deg) const;
  // The zones' solid angle in steradians (overlaps counted twice: an upper bound on the union's).
  double zone_area() const;
  // The grid spacing that covers the region with about `count` candidates (finer for a small cap),
  // within [min_deg, max_deg].
  double grid_step_for(int count, double min_deg = 0.25, double max_deg = 4.0) const;
  // The zone x lies in most deeply (tilt farthest from both of its bounds), or -1 outside every zone.
  int deepest_zone(const Vec3& x) const;

  // Whether the signed permutation g maps the region onto itself (zones onto zones with the same
  // tilts, candidates onto candidates). Every criterion is invariant under signed permutations, so
  // an optimal measure may then be taken invariant under g too.
  bool invariant_under(const Mat3& g) const;
  // The half-meridians of the zone an optimal measure may be confined to: when the signed
  // permutations that fix the zone's axis and map the region onto itself include k >= 3 rotations
  // about it and a mirror, an invariant measure's circles about the axis see only the mean and the
  // k-th harmonic of their azimuths (the information matrix holds moments up to degree 4, and the
  // symmetry removes the other harmonics up to 4), and the two k-point orbits at the mirror's
  // azimuth and half a step off carry every such circle's information. So the azimuths (degrees,
  // in the zone's azimuth_frame) are 2k, 180/k apart: 8 about a coordinate axis, 6 about a cube
  // diagonal. Empty when there is no such reduction.
  std::vector<double> meridians(const Zone& zone) const;
  // Candidates for an optimal measure: grid(step_deg), except that a zone with meridians is
  // covered only along them, step_deg / 4 apart in tilt.
  std::vector<Vec3> measure_grid(double step_deg) const;
};

// The azimuth frame of an axis a: e1 is the direction of +x projected on the plane normal to a (of
// +y when a is within about 26 degrees of the x axis), e2 = a x e1. For a = +z: e1 = +x, e2 = +y.
std::pair<Vec3, Vec3> azimuth_frame(const Vec3& axis);
// Tilt from the zone's axis and azimuth in its frame (degrees, azimuth in [0, 360)).
double azimuth_deg(const Zone& zone, const Vec3& x);
// The position at a tilt and an azimuth (degrees) of the zone's axis and frame.
Vec3 zone_position(const Zone& zone, double tilt_deg, double azimuth_deg);

// The signed permutations of the axes that fix `axis` (the identity at least).
std::vector<Mat3> symmetries_fixing(const Vec3& axis);

Region sphere_region();

// The region with every zone boundary moved inwards by margin_deg (a cap's rim, a band's two
// circles; the sphere has none), candidates kept: where optimize --margin designs, so that a
// bench's rounding or misalignment keeps the positions inside the region itself. Throws InputError
// ("--margin") when a zone would vanish.
Region inset_region(const Region& region, double margin_deg);

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
