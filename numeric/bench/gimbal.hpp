// gimbal:A1,A2[,A3][:limits=LO..HI,LO..HI[,LO..HI]]: a two- or three-axis rotary table, its axes
// from the outer to the inner one, each given as the meter axis (x, y, z, -x, ...) it lies along at
// zero angles. R = R_A1(theta1) R_A2(theta2) [R_A3(theta3)]: the outer axis is fixed in the lab and
// each inner one turns with the axes outside it, and eta = R^T (0, 0, 1). Without limits every axis
// turns without stops; with them each stays within its LO..HI (degrees).
//
// Two axes reach a position at the (at most two) intersections of two circles (two_axis_angles);
// three axes reach it in a one-parameter family, sampled at 12 angles of the outer axis (its angle
// is free when it is vertical: it then turns the meter about the measured vector).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "numeric/bench/bench.hpp"
#include "numeric/bench/bench_spec.hpp"

namespace scalcal {

struct GimbalBench {
  static constexpr std::string_view name = "gimbal";
  static constexpr std::string_view syntax = "gimbal:A1,A2[,A3][:limits=LO..HI,LO..HI[,LO..HI]]";
  static constexpr std::string_view summary =
      "a two- or three-axis rotary table, axes outer to inner as meter axes at zero angles";
  static constexpr std::string_view mounting_key = "mounting";
  static constexpr bool kAnglesAsArray = true;
  static constexpr int kOuterSamples = 12;

  std::vector<Vec3> directions;  // unit, outer first
  std::vector<BenchAxis> axis_list;
  std::vector<Mounting> mounting_list{Mounting{"mounted", "mounted", Mat3::Identity()}};
  bool limited = false;

  static GimbalBench parse(std::string_view params) {
    const std::string spec = "gimbal:" + std::string(params);
    const auto parts = split_spec(params, ':');
    if (parts.size() > 2 || parts[0].empty()) bench_error(spec, std::string("expected ") + std::string(syntax));
    GimbalBench g;
    for (const auto& a : split_spec(parts[0], ',')) g.directions.push_back(spec_axis(spec, a));
    if (g.directions.size() < 2 || g.directions.size() > 3)
      bench_error(spec, "a gimbal has two or three axes, got " + std::to_string(g.directions.size()));
    for (std::size_t k = 1; k < g.directions.size(); ++k)
      if (std::abs(g.directions[k].dot(g.directions[k - 1])) > 0.5)
        bench_error(spec, "axes " + std::to_string(k) + " and " + std::to_string(k + 1) +
                              " are parallel: adjacent gimbal axes must differ");
    for (std::size_t k = 0; k < g.directions.size(); ++k)
      g.axis_list.push_back(BenchAxis{"theta" + std::to_string(k + 1) + "_deg"});
    if (parts.size() == 2) g.read_limits(spec, parts[1]);
    return g;
  }

  std::string text() const {
    std::string s = "gimbal:";
    for (std::size_t k = 0; k < directions.size(); ++k) s += (k ? "," : "") + axis_text(directions[k]);
    if (!limited) return s;
    s += ":limits=";
    for (std::size_t k = 0; k < axis_list.size(); ++k)
      s += (k ? "," : "") + number_text(axis_list[k].lo) + ".." + number_text(axis_list[k].hi);
    return s;
  }

  const std::vector<BenchAxis>& axes() const { return axis_list; }
  const std::vector<Mounting>& mountings() const { return mounting_list; }

  Mat3 orientation(const BenchSetting& s) const {
    Mat3 R = Mat3::Identity();
    for (std::size_t k = 0; k < directions.size(); ++k)
      R = R * axis_rotation(directions[k], std::isnan(s.angles[k]) ? 0.0 : s.angles[k]);
    return R;
  }

  std::vector<BenchSetting> settings(const Vec3& eta) const {
    std::vector<BenchSetting> out;
    const Vec3 up = Vec3::UnitZ();
    const auto add = [&](double outer, const Vec3& a1, const Vec3& a2, const Vec3& v) {
      for (const auto& [t1, t2] : two_axis_angles(a1, a2, v, eta)) {
        std::vector<double> solved =
            directions.size() == 2 ? std::vector<double>{t1, t2} : std::vector<double>{outer, t1, t2};
        expand_settings(0, axis_list, solved, out);
      }
    };
    if (directions.size() == 2) {
      add(0, directions[0], directions[1], up);
    } else if (std::abs(directions[0].dot(up)) > 1 - 1e-15) {
      add(std::nan(""), directions[1], directions[2], up);  // a vertical outer axis turns about the vector
    } else {
      for (const double t0 : outer_samples())
        add(t0, directions[1], directions[2], axis_rotation(directions[0], t0).transpose() * up);
    }
    // Keep what measures eta (a sampled outer angle may leave none; a degenerate branch is dropped);
    // a position taken on the edge of the reach is within the slack of it.
    std::erase_if(out, [&](const BenchSetting& s) {
      return (position_of_orientation(orientation(s)) - eta).norm() > 2 * kLimitSlackDeg * kDegree;
    });
    return out;
  }

 private:
  static std::string number_text(double v) {
    std::string s = std::to_string(v);
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s;
  }

  void read_limits(const std::string& spec, const std::string& field) {
    if (!field.starts_with("limits=")) bench_error(spec, "expected limits=LO..HI,... after the axes");
    const auto ranges = split_spec(std::string_view(field).substr(7), ',');
    if (ranges.size() != axis_list.size())
      bench_error(spec, std::to_string(axis_list.size()) + " axes need " + std::to_string(axis_list.size()) +
                            " limits LO..HI, got " + std::to_string(ranges.size()));
    for (std::size_t k = 0; k < ranges.size(); ++k) {
      const auto dots = ranges[k].find("..");
      if (dots == std::string::npos) bench_error(spec, "a limit is LO..HI (degrees), got '" + ranges[k] + "'");
      BenchAxis& a = axis_list[k];
      a.lo = spec_number(spec, ranges[k].substr(0, dots), "a lower limit");
      a.hi = spec_number(spec, ranges[k].substr(dots + 2), "an upper limit");
      if (!(a.lo < a.hi) || a.hi - a.lo > 720)
        bench_error(spec, "limits '" + ranges[k] + "' must have LO < HI and span at most 720 degrees");
      a.continuous = false;
    }
    limited = true;
  }

  // The outer angles a three-axis gimbal is tried at: 12 across its range (every 30 degrees when it
  // turns freely), and 0 when the range holds it.
  std::vector<double> outer_samples() const {
    const BenchAxis& a = axis_list[0];
    std::vector<double> t;
    if (a.continuous) {
      for (int k = 0; k < kOuterSamples; ++k) t.push_back(-150.0 + 30.0 * k);
      return t;
    }
    for (int k = 0; k < kOuterSamples; ++k) t.push_back(a.lo + (a.hi - a.lo) * k / (kOuterSamples - 1));
    if (a.lo < 0 && a.hi > 0) t.push_back(0);
    return t;
  }
};

}  // namespace scalcal
