// faces[:DEG]: the meter set down on each of its six faces on a plate that tilts up to DEG degrees
// either way (default 0: a level plate, the six axis positions), turned about the plate's normal;
// changing the face down is a remount. The settings are a tilt table's (tilt_table.hpp) for the
// mounting with that face down: tilt_deg and turn_deg (the azimuth). It reaches faces:DEG.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "numeric/bench/bench_spec.hpp"
#include "numeric/bench/tilt_table.hpp"

namespace scalcal {

struct FacesBench {
  static constexpr std::string_view name = "faces";
  static constexpr std::string_view syntax = "faces[:DEG]";
  static constexpr std::string_view summary =
      "the meter on each of its six faces (the face down), turned about the vertical, on a plate tilting up to DEG "
      "(default 0)";
  static constexpr std::string_view mounting_key = "face_down";

  double max_tilt_deg = 0;
  std::vector<BenchAxis> axis_list;
  std::vector<Mounting> mounting_list;

  static FacesBench parse(std::string_view params) {
    const std::string spec = "faces" + (params.empty() ? std::string() : ":" + std::string(params));
    FacesBench b;
    if (!params.empty()) b.max_tilt_deg = spec_number(spec, std::string(params), "the tilt DEG");
    if (!(b.max_tilt_deg >= 0 && b.max_tilt_deg <= 180)) bench_error(spec, "the tilt DEG must be in [0, 180]");
    b.axis_list = {BenchAxis{"tilt_deg", -b.max_tilt_deg, b.max_tilt_deg, false}, BenchAxis{"turn_deg"}};
    // The face down is the one opposite the axis that points up.
    const Vec3 up[6] = {Vec3::UnitZ(), -Vec3::UnitZ(), Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY()};
    for (const Vec3& u : up) {
      const std::string down = axis_text(-u);
      b.mounting_list.push_back(
          Mounting{"face " + down + " down (" + axis_text(u) + " up)", down, mounting_rotation(u)});
    }
    return b;
  }

  std::string text() const {
    if (max_tilt_deg == 0) return "faces";
    std::string s = std::to_string(max_tilt_deg);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return "faces:" + s;
  }
  const std::vector<BenchAxis>& axes() const { return axis_list; }
  const std::vector<Mounting>& mountings() const { return mounting_list; }
  Mat3 orientation(const BenchSetting& s) const { return tilt_table_orientation(mounting_list, s); }
  std::vector<BenchSetting> settings(const Vec3& eta) const {
    return tilt_table_settings(mounting_list, axis_list, eta);
  }
};

}  // namespace scalcal
