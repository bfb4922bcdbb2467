// tilt:DEG[:flip]: a tilt table (tilt_table.hpp) whose plate tilts up to DEG degrees either way, the
// meter mounted upright (+z up at zero tilt); with :flip it may also be turned over (-z up), a remount
// by hand. It reaches cap:DEG (with :flip, cap:DEG and cap:DEG:0,0,-1).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "numeric/bench/bench_spec.hpp"
#include "numeric/bench/tilt_table.hpp"

namespace scalcal {

struct TiltBench {
  static constexpr std::string_view name = "tilt";
  static constexpr std::string_view syntax = "tilt:DEG[:flip]";
  static constexpr std::string_view summary =
      "a tilt table: tilt up to DEG either way and azimuth (turntable); :flip also mounts the meter upside down";
  static constexpr std::string_view mounting_key = "mounting";

  double max_tilt_deg = 0;
  bool flip = false;
  std::vector<BenchAxis> axis_list;
  std::vector<Mounting> mounting_list;

  static TiltBench parse(std::string_view params) {
    const std::string spec = "tilt:" + std::string(params);
    const auto parts = split_spec(params, ':');
    if (parts.size() > 2 || (parts.size() == 2 && parts[1] != "flip"))
      bench_error(spec, std::string("expected ") + std::string(syntax));
    TiltBench b;
    b.max_tilt_deg = spec_number(spec, parts[0], "the tilt DEG");
    if (!(b.max_tilt_deg > 0 && b.max_tilt_deg <= 180)) bench_error(spec, "the tilt DEG must be in (0, 180]");
    b.flip = parts.size() == 2;
    b.axis_list = {BenchAxis{"tilt_deg", -b.max_tilt_deg, b.max_tilt_deg, false}, BenchAxis{"azimuth_deg"}};
    b.mounting_list = {Mounting{"+z up", "upright", mounting_rotation(Vec3::UnitZ())}};
    if (b.flip)
      b.mounting_list.push_back(Mounting{"-z up (turned over)", "flipped", mounting_rotation(-Vec3::UnitZ())});
    return b;
  }

  std::string text() const {
    std::string s = std::to_string(max_tilt_deg);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return "tilt:" + s + (flip ? ":flip" : "");
  }
  const std::vector<BenchAxis>& axes() const { return axis_list; }
  const std::vector<Mounting>& mountings() const { return mounting_list; }
  Mat3 orientation(const BenchSetting& s) const { return tilt_table_orientation(mounting_list, s); }
  std::vector<BenchSetting> settings(const Vec3& eta) const {
    return tilt_table_settings(mounting_list, axis_list, eta);
  }
};

}  // namespace scalcal
