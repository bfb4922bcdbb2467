// rate:DEG:RPM:SECONDS[:flip]: a single-axis rate table (vertical axis) carrying the meter on a
// tilting fixture (tilt_table.hpp: tilt up to DEG either way, azimuth on the fixture's turntable,
// :flip also mounts it upside down), turning at RPM revolutions per minute for SECONDS per segment.
// A gyro's position is the table's axis in the meter's frame signed by the turn (Theorem 24 of
// proofs/gyro_rate_table.md), so each mounting measures its axis turning counterclockwise seen from
// above (rate +RPM) and the antipode turning clockwise (rate -RPM), without a remount: the axis
// rate_rpm of a setting is the turn's rate and direction, and its `seconds` how long the segment
// runs (every segment SECONDS: the two are bench axes so that a plan says them step by step). It
// reaches the tilt table's region and its antipode. orientation() of a clockwise setting is the
// fixture's turned half over about the lab's x axis: its row 2 (the position) is then the antipode,
// as the gyro sees it; the fixture itself is set as for the counterclockwise one.
#pragma once
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "numeric/bench/bench_spec.hpp"
#include "numeric/bench/tilt_table.hpp"

namespace scalcal {

struct RateTableBench {
  static constexpr std::string_view name = "rate";
  static constexpr std::string_view syntax = "rate:DEG:RPM:SECONDS[:flip]";
  static constexpr std::string_view summary =
      "a single-axis rate table (gyros): a tilting fixture (tilt up to DEG, azimuth) on a table turning RPM either way "
      "for SECONDS per segment; :flip also mounts the meter upside down";
  static constexpr std::string_view mounting_key = "mounting";

  double max_tilt_deg = 0, rpm = 0, seconds = 0;
  bool flip = false;
  std::vector<BenchAxis> axis_list;
  std::vector<Mounting> mounting_list;

  static RateTableBench parse(std::string_view params) {
    const std::string spec = "rate:" + std::string(params);
    const auto parts = split_spec(params, ':');
    if (parts.size() < 3 || parts.size() > 4 || (parts.size() == 4 && parts[3] != "flip"))
      bench_error(spec, std::string("expected ") + std::string(syntax));
    RateTableBench b;
    b.max_tilt_deg = spec_number(spec, parts[0], "the tilt DEG");
    b.rpm = spec_number(spec, parts[1], "the rate RPM");
    b.seconds = spec_number(spec, parts[2], "the segment's SECONDS");
    if (!(b.max_tilt_deg >= 0 && b.max_tilt_deg <= 180)) bench_error(spec, "the tilt DEG must be in [0, 180]");
    // The rate is a bench axis, and axes hold values in (-180, 180].
    if (!(b.rpm > 0 && b.rpm < 180)) bench_error(spec, "the rate RPM must be in (0, 180) revolutions per minute");
    if (!(b.seconds > 0 && b.seconds <= 180)) bench_error(spec, "the segment's SECONDS must be in (0, 180]");
    b.flip = parts.size() == 4;
    b.axis_list = {BenchAxis{"tilt_deg", -b.max_tilt_deg, b.max_tilt_deg, false}, BenchAxis{"azimuth_deg"},
                   BenchAxis{"rate_rpm", -b.rpm, b.rpm, false}, BenchAxis{"seconds", b.seconds, b.seconds, false}};
    b.mounting_list = {Mounting{"+z up", "upright", mounting_rotation(Vec3::UnitZ())}};
    if (b.flip)
      b.mounting_list.push_back(Mounting{"-z up (turned over)", "flipped", mounting_rotation(-Vec3::UnitZ())});
    return b;
  }

  std::string text() const {
    auto number = [](double v) {
      std::string s = std::to_string(v);
      s.erase(s.find_last_not_of('0') + 1);
      if (s.back() == '.') s.pop_back();
      return s;
    };
    return "rate:" + number(max_tilt_deg) + ":" + number(rpm) + ":" + number(seconds) + (flip ? ":flip" : "");
  }
  const std::vector<BenchAxis>& axes() const { return axis_list; }
  const std::vector<Mounting>& mountings() const { return mounting_list; }
  Mat3 orientation(const BenchSetting& s) const {
    const BenchSetting fixture{s.mounting, {s.angles[0], s.angles[1]}};
    const Mat3 R = tilt_table_orientation(mounting_list, fixture);
    return s.angles[2] > 0 ? R : Mat3(Vec3(1, -1, -1).asDiagonal() * R);
  }
  std::vector<BenchSetting> settings(const Vec3& eta) const {
    std::vector<BenchSetting> out;
    const std::vector<BenchAxis> fixture_axes(axis_list.begin(), axis_list.begin() + 2);
    for (double sense : {1.0, -1.0})
      for (BenchSetting s : tilt_table_settings(mounting_list, fixture_axes, sense * eta)) {
        s.angles.push_back(sense * rpm);
        s.angles.push_back(seconds);
        out.push_back(std::move(s));
      }
    return out;
  }
  // Reversing the table is no travel of the fixture.
  double travel(const BenchSetting& a, const BenchSetting& b) const {
    return axis_travel(axis_list[0], a.angles[0], b.angles[0]) + axis_travel(axis_list[1], a.angles[1], b.angles[1]);
  }
};

}  // namespace scalcal
