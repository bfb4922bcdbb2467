// jig:NAME: a printable polyhedral jig (`scalcal family jig:NAME`, default mounting of the meter in
// it) set down on one face after another. Its program's positions are the faces' outer normals n_f,
// numbered as `evaluate jig:NAME` numbers them; resting on face f, the face's normal points down,
// so the position measured is eta = -n_f: a position eta is run with the face whose normal is -eta
// down (every printable jig is centrally symmetric, so that face exists). Tipping the jig from face
// to face is no remount (the meter stays in the jig); its travel is the angle tipped.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "numeric/bench/bench.hpp"
#include "numeric/bench/bench_spec.hpp"
#include "numeric/program/catalogue.hpp"

namespace scalcal {

struct JigBench {
  static constexpr std::string_view name = "jig";
  static constexpr std::string_view syntax = "jig:NAME";
  static constexpr std::string_view summary = "a printable jig (scalcal family jig:NAME), one face down per position";
  static constexpr std::string_view mounting_key = "face_down";
  static constexpr bool kRemounts = false;

  std::string jig;
  std::vector<Vec3> normals;  // outer face normals, unit
  std::vector<Mounting> mounting_list;

  // The jig's faces come from the program names registered by the symbolic families.
  static JigBench parse(std::string_view params) {
    const std::string spec = "jig:" + std::string(params);
    JigBench b;
    b.jig = std::string(params);
    std::optional<Program> faces;
    if (!b.jig.empty() && b.jig.find(':') == std::string::npos) faces = named_program("jig:" + b.jig);
    if (!faces) bench_error(spec, "no printable jig of that name (see `scalcal catalogue`, group jig)");
    for (std::size_t f = 0; f < faces->positions.size(); ++f) {
      const Vec3 n = faces->positions[f].normalized();
      b.normals.push_back(n);
      const std::string number = std::to_string(f + 1);
      b.mounting_list.push_back(Mounting{"face " + number + " down", number, mounting_rotation(-n)});
    }
    return b;
  }

  std::string text() const { return "jig:" + jig; }
  const std::vector<BenchAxis>& axes() const {
    static const std::vector<BenchAxis> none;
    return none;
  }
  const std::vector<Mounting>& mountings() const { return mounting_list; }
  Mat3 orientation(const BenchSetting& s) const { return mounting_list[static_cast<std::size_t>(s.mounting)].rotation; }

  // The face whose normal is -eta (to 1e-6).
  std::vector<BenchSetting> settings(const Vec3& eta) const {
    std::vector<BenchSetting> out;
    for (std::size_t f = 0; f < normals.size(); ++f)
      if ((normals[f] + eta).norm() < 1e-6) out.push_back(BenchSetting{static_cast<int>(f), {}});
    return out;
  }

  // The angle the jig is tipped through from one face to the next (degrees).
  double travel(const BenchSetting& a, const BenchSetting& b) const {
    const Vec3 &p = normals[static_cast<std::size_t>(a.mounting)], &q = normals[static_cast<std::size_t>(b.mounting)];
    return std::atan2(p.cross(q).norm(), p.dot(q)) / kDegree;
  }
};

}  // namespace scalcal
