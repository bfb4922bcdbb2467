// The directions a bench can reach, parsed from --region specs (region.hpp).
#include "numeric/region/region.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>

#include <Eigen/Eigenvalues>

#include "numeric/criteria/evaluation.hpp"
#include "numeric/criteria/identifiability.hpp"
#include "numeric/io/input_error.hpp"
#include "numeric/io/option_words.hpp"
#include "numeric/model/direction.hpp"
#include "numeric/program/program_csv.hpp"

namespace scalcal {
namespace {

[[noreturn]] void bad_spec(const std::string& spec, const std::string& reason) {
  throw InputError(option_word("region"), 0, "'" + display_name(spec) + "': " + reason);
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out(1);
  for (char c : s) {
    if (c == sep)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

double number(const std::string& spec, const std::string& text, const char* what) {
  double v = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v))
    bad_spec(spec, std::string(what) + " '" + display_name(text) + "' is not a number");
  return v;
}

double angle(const std::string& spec, const std::string& text, const char* what, double lo, double hi) {
  const double v = number(spec, text, what);
  if (v < lo || v > hi)
    bad_spec(spec, std::string(what) + " " + text + " is outside [" + std::to_string(static_cast<int>(lo)) + ", " +
                       std::to_string(static_cast<int>(hi)) + "] degrees");
  return v;
}

Vec3 axis(const std::string& spec, const std::string& text) {
  const auto parts = split(text, ',');
  if (parts.size() != 3) bad_spec(spec, "the axis must be X,Y,Z (three numbers), not '" + display_name(text) + "'");
  const Vec3 a(number(spec, parts[0], "axis x"), number(spec, parts[1], "axis y"), number(spec, parts[2], "axis z"));
  const std::optional<Vec3> u = unit_direction(a);
  if (!u) bad_spec(spec, "the axis is the zero vector");
  return *u;
}

void add_zone_rings(const Zone& z, double step_deg, std::vector<Vec3>& out) {
  const double deg = std::numbers::pi / 180.0;
  const auto [e1, e2] = azimuth_frame(z.axis);
  const double span = z.max_tilt_deg - z.min_tilt_deg;
  const int rings = std::max(1, static_cast<int>(std::ceil(span / step_deg)));
  for (int i = 0; i <= rings; ++i) {
    const double tilt = (z.min_tilt_deg + span * i / rings) * deg;
    const double s = std::sin(tilt), c = std::cos(tilt);
    const int around = std::max(1, static_cast<int>(std::ceil(360.0 * s / step_deg)));
    if (s < 1e-12) {  // a pole: one position
      out.push_back(c > 0 ? z.axis : Vec3(-z.axis));
      continue;
    }
    for (int j = 0; j < around; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / around;
      out.push_back((s * std::cos(phi) * e1 + s * std::sin(phi) * e2 + c * z.axis).normalized());
    }
  }
}

}  // namespace

std::pair<Vec3, Vec3> azimuth_frame(const Vec3& axis) {
  const Vec3 ref = std::abs(axis.x()) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const Vec3 e1 = (ref - ref.dot(axis) * axis).normalized();
  return {e1, axis.cross(e1)};
}

double azimuth_deg(const Zone& zone, const Vec3& x) {
  const auto [e1, e2] = azimuth_frame(zone.axis);
  double a = std::atan2(e2.dot(x), e1.dot(x)) * 180.0 / std::numbers::pi;
  if (a < 0) a += 360.0;
  return a >= 360.0 ? 0.0 : a;
}

double Region::zone_area() const {
  const double deg = std::numbers::pi / 180.0;
  double out = 0;
  for (const auto& z : zones)
    out += 2 * std::numbers::pi * (std::cos(z.min_tilt_deg * deg) - std::cos(z.max_tilt_deg * deg));
  return out;
}

double Region::grid_step_for(int count, double min_deg, double max_deg) const {
  const double square_deg = zone_area() * (180.0 / std::numbers::pi) * (180.0 / std::numbers::pi);
  return std::clamp(std::sqrt(square_deg / std::max(count, 1)), min_deg, max_deg);
}

int Region::deepest_zone(const Vec3& x) const {
  int best = -1;
  double depth = -kRegionToleranceDeg;
  for (std::size_t k = 0; k < zones.size(); ++k) {
    const double t = zones[k].tilt_deg(x);
    const double d = std::min(t - zones[k].min_tilt_deg, zones[k].max_tilt_deg - t);
    if (d >= depth) {
      depth = d;
      best = static_cast<int>(k);
    }
  }
  return best;
}

Vec3 zone_position(const Zone& zone, double tilt_deg, double az_deg) {
  const double deg = std::numbers::pi / 180.0;
  const auto [e1, e2] = azimuth_frame(zone.axis);
  const double t = tilt_deg * deg, a = az_deg * deg;
  return (std::sin(t) * (std::cos(a) * e1 + std::sin(a) * e2) + std::cos(t) * zone.axis).normalized();
}

std::vector<Mat3> symmetries_fixing(const Vec3& axis) {
  std::vector<Mat3> out;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : perms)
    for (int signs = 0; signs < 8; ++signs) {
      Mat3 g = Mat3::Zero();
      for (int r = 0; r < 3; ++r) g(r, p[r]) = (signs >> r) & 1 ? -1.0 : 1.0;
      if ((g * axis - axis).norm() < 1e-12) out.push_back(g);
    }
  return out;
}

bool Region::invariant_under(const Mat3& g) const {
  constexpr double kSame = 1e-9;
  for (const Zone& z : zones) {
    const Vec3 image = g * z.axis;
    const bool found = std::any_of(zones.begin(), zones.end(),
                                   [&](const Zone& o) {
                                     return std::abs(o.min_tilt_deg - z.min_tilt_deg) < kSame &&
                                            std::abs(o.max_tilt_deg - z.max_tilt_deg) < kSame &&
                                            (o.axis - image).norm() < kSame;
                                   }) ||
                       (z.is_sphere());
    if (!found) return false;
  }
  for (const Vec3& c : candidates) {
    const Vec3 image = g * c;
    if (std::none_of(candidates.begin(), candidates.end(), [&](const Vec3& o) { return (o - image).norm() < 1e-9; }))
      return false;
  }
  return true;
}

std::vector<double> Region::meridians(const Zone& zone) const {
  int rotations = 0;
  std::optional<Mat3> mirror;
  for (const Mat3& g : symmetries_fixing(zone.axis)) {
    if (!invariant_under(g)) continue;
    if (g.determinant() > 0)
      ++rotations;
    else
      mirror = g;
  }
  if (rotations < 3 || !mirror) return {};
  // The mirror's plane holds the axis and the direction axis x n, n its normal (eigenvalue -1).
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(*mirror);
  const Vec3 in_plane = zone.axis.cross(eig.eigenvectors().col(0));
  const double offset = azimuth_deg(zone, in_plane.normalized());
  std::vector<double> out;
  for (int j = 0; j < 2 * rotations; ++j) out.push_back(std::fmod(offset + 180.0 * j / rotations, 360.0));
  return out;
}

std::vector<Vec3> Region::measure_grid(double step_deg) const {
  std::vector<Vec3> out = candidates;
  for (const Zone& z : zones) {
    const std::vector<double> azimuths = meridians(z);
    if (azimuths.empty()) {
      add_zone_rings(z, step_deg, out);
      continue;
    }
    const double span = z.max_tilt_deg - z.min_tilt_deg;
    const int rings = std::max(1, static_cast<int>(std::ceil(4 * span / step_deg)));
    for (int i = 0; i <= rings; ++i) {
      const double tilt = z.min_tilt_deg + span * i / rings;
      if (tilt <= 0.0 || tilt >= 180.0) {  // a pole: one position
        out.push_back(tilt <= 0.0 ? z.axis : Vec3(-z.axis));
        continue;
      }
      for (double a : azimuths) out.push_back(zone_position(z, tilt, a));
    }
  }
  return out;
}

bool Region::is_sphere() const {
  for (const auto& z : zones)
    if (z.is_sphere()) return true;
  return false;
}

bool Region::contains(const Vec3& x, double tolerance_deg) const {
  for (const auto& z : zones)
    if (z.contains(x, tolerance_deg)) return true;
  const double cos_tol = std::cos(tolerance_deg * std::numbers::pi / 180.0);
  for (const auto& c : candidates)
    if (c.dot(x) >= cos_tol) return true;
  return false;
}

std::string Region::text() const {
  std::string out;
  for (const auto& s : specs) out += (out.empty() ? "" : " + ") + s;
  if (out.empty()) out = "sphere";
  if (inset_deg > 0) {
    char margin[32];
    std::snprintf(margin, sizeof margin, "%.6g", inset_deg);
    out += std::string(" inset by ") + margin + " deg";
  }
  return out;
}

std::vector<Vec3> Region::grid(double step_deg) const {
  std::vector<Vec3> out = candidates;
  for (const auto& z : zones) add_zone_rings(z, step_deg, out);
  return out;
}

Region sphere_region() {
  Region r;
  r.specs = {"sphere"};
  r.zones = {Zone{}};
  return r;
}

void add_region_spec(Region& region, const std::string& spec) {
  const auto colon = spec.find(':');
  const std::string kind = spec.substr(0, colon);
  const std::string rest = colon == std::string::npos ? "" : spec.substr(colon + 1);
  if (kind == "candidates") {
    if (rest.empty()) bad_spec(spec, "candidates needs a program file: candidates:FILE");
    const Program p = read_program_csv(rest);  // InputError names the file and line
    region.candidates.insert(region.candidates.end(), p.positions.begin(), p.positions.end());
    region.specs.push_back(spec);
    return;
  }
  const auto parts = colon == std::string::npos ? std::vector<std::string>{} : split(rest, ':');
  if (kind == "sphere") {
    if (!parts.empty()) bad_spec(spec, "sphere takes no arguments");
    region.zones.push_back(Zone{});
  } else if (kind == "cap") {
    if (parts.empty() || parts.size() > 2) bad_spec(spec, "expected cap:DEG or cap:DEG:X,Y,Z");
    const double deg = angle(spec, parts[0], "the half-angle", 0, 180);
    if (!(deg > 0)) bad_spec(spec, "a cap of 0 degrees is a single direction; use candidates:FILE");
    region.zones.push_back(Zone{parts.size() == 2 ? axis(spec, parts[1]) : Vec3(0, 0, 1), 0.0, deg});
  } else if (kind == "band") {
    if (parts.size() < 2 || parts.size() > 3) bad_spec(spec, "expected band:LO:HI or band:LO:HI:X,Y,Z");
    const double lo = angle(spec, parts[0], "LO", 0, 180), hi = angle(spec, parts[1], "HI", 0, 180);
    if (!(lo < hi)) bad_spec(spec, "LO must be less than HI (a band of zero width is one circle)");
    region.zones.push_back(Zone{parts.size() == 3 ? axis(spec, parts[2]) : Vec3(0, 0, 1), lo, hi});
  } else if (kind == "faces") {
    if (parts.size() != 1) bad_spec(spec, "expected faces:DEG");
    const double deg = angle(spec, parts[0], "the half-angle", 0, 180);
    if (!(deg > 0)) bad_spec(spec, "faces of 0 degrees are the six axis directions; use candidates:FILE");
    for (int a = 0; a < 3; ++a)
      for (double s : {1.0, -1.0}) {
        Vec3 v = Vec3::Zero();
        v(a) = s;
        region.zones.push_back(Zone{v, 0.0, deg});
      }
  } else {
    bad_spec(spec, "unknown region '" + display_name(kind) +
                       "'; expected sphere, cap:DEG[:X,Y,Z], band:LO:HI[:X,Y,Z], faces:DEG or candidates:FILE");
  }
  region.specs.push_back(spec);
}

Region inset_region(const Region& region, double margin_deg) {
  Region r = region;
  if (!(margin_deg > 0)) return r;
  r.inset_deg += margin_deg;
  for (Zone& z : r.zones) {
    if (z.is_sphere()) continue;
    if (z.min_tilt_deg > 0) z.min_tilt_deg += margin_deg;
    if (z.max_tilt_deg < 180) z.max_tilt_deg -= margin_deg;
    if (!(z.min_tilt_deg < z.max_tilt_deg)) {
      char text[64];
      std::snprintf(text, sizeof text, "%.6g", margin_deg);
      throw InputError(option_word("margin"), 0,
                       std::string(text) + " degrees leaves nothing of the region " + region.text());
    }
  }
  return r;
}

Region parse_region(const std::vector<std::string>& specs) {
  if (specs.empty()) return sphere_region();
  Region r;
  for (const auto& s : specs) {
    const std::size_t before = r.zones.size();
    add_region_spec(r, s);
    // A zone given again adds nothing to the union, but would be counted twice by the candidate
    // grids and solid angles: 32 copies of one cap gave 12x the candidates and a proven A bound
    // 0.45 below the optimum instead of 2e-5. The repeated spec is dropped whole.
    const auto same = [&](const Zone& a, const Zone& b) {
      return a.axis == b.axis && a.min_tilt_deg == b.min_tilt_deg && a.max_tilt_deg == b.max_tilt_deg;
    };
    bool repeated = r.zones.size() > before;
    for (std::size_t k = before; k < r.zones.size() && repeated; ++k)
      repeated = std::any_of(r.zones.begin(), r.zones.begin() + static_cast<std::ptrdiff_t>(before),
                             [&](const Zone& z) { return same(z, r.zones[k]); });
    if (repeated) {
      r.zones.resize(before);
      r.specs.pop_back();
    }
  }
  return r;
}

double check_region_identifiable(const Region& region) {
  Program grid;  // fine enough that even a cap of a fraction of a degree gets many positions
  grid.positions = region.grid(region.grid_step_for(500, 0.001, 4.0));
  constexpr int kParameters = 9;  // the paper's model, which evaluate() fits
  if (grid.size() < kParameters)
    throw InputError(option_word("region"), 0,
                     "'" + display_name(region.text()) + "' has only " + std::to_string(grid.size()) +
                         " distinct positions; the model needs at least 9");
  const Evaluation ev = evaluate(grid);
  if (!ev.full_rank())
    throw InputError(option_word("region"), 0,
                     "no program on '" + display_name(region.text()) + "' is rank 9: " + rank_deficiency(ev));
  return ev.condition;
}

}  // namespace scalcal
