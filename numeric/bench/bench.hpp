// What a bench type must give (a missing piece is a compile error where the bench is registered):
//   name, syntax, summary         its --bench name, the spec after "name:", one line for help
//   parse(params)                 the bench from the text after "name:" (InputError "--bench" if bad)
//   text()                        the spec, canonical
//   axes(), mountings()           its axes (names, limits) and the ways the meter is fixed to it
//   mounting_key                  the JSON key of a setting's mounting ("mounting", "face_down")
//   orientation(setting)          R, the meter's frame to the lab's (kinematics.hpp)
//   settings(eta)                 every setting that measures eta (empty: out of reach)
// and may give travel(a, b) (default: the sum of its axes' turns), kRemounts (default true: changing
// the mounting is a remount by hand) and kAnglesAsArray (JSON `angles_deg` instead of one key per
// axis). Solvers and `plan` see a bench only through these, never through its name.
#pragma once
#include <concepts>
#include <string>
#include <string_view>
#include <vector>

#include "numeric/bench/kinematics.hpp"

namespace scalcal {

template <class B>
concept BenchType = requires(const B b, const BenchSetting& s, const Vec3& eta, std::string_view params) {
  { B::name } -> std::convertible_to<std::string_view>;
  { B::syntax } -> std::convertible_to<std::string_view>;
  { B::summary } -> std::convertible_to<std::string_view>;
  { B::mounting_key } -> std::convertible_to<std::string_view>;
  { B::parse(params) } -> std::same_as<B>;
  { b.text() } -> std::convertible_to<std::string>;
  { b.axes() } -> std::convertible_to<const std::vector<BenchAxis>&>;
  { b.mountings() } -> std::convertible_to<const std::vector<Mounting>&>;
  { b.orientation(s) } -> std::same_as<Mat3>;
  { b.settings(eta) } -> std::same_as<std::vector<BenchSetting>>;
};

// How far a bench moves between two settings: its own travel when it has one, else the sum of its
// axes' turns (degrees).
template <BenchType B>
double bench_travel(const B& bench, const BenchSetting& a, const BenchSetting& b) {
  if constexpr (requires { bench.travel(a, b); }) {
    return bench.travel(a, b);
  } else {
    double t = 0;
    const auto& axes = bench.axes();
    for (std::size_t k = 0; k < axes.size(); ++k) t += axis_travel(axes[k], a.angles[k], b.angles[k]);
    return t;
  }
}

// Whether going from a to b takes a remount by hand.
template <BenchType B>
bool bench_remount(const B&, const BenchSetting& a, const BenchSetting& b) {
  if constexpr (requires { B::kRemounts; }) {
    if (!B::kRemounts) return false;
  }
  return a.mounting != b.mounting;
}

template <BenchType B>
constexpr bool bench_angles_as_array() {
  if constexpr (requires { B::kAnglesAsArray; })
    return B::kAnglesAsArray;
  else
    return false;
}

// Each cartesian combination of per-axis values (axis_values): the ways to write solved angles.
inline void expand_settings(int mounting, const std::vector<BenchAxis>& axes, const std::vector<double>& solved,
                            std::vector<BenchSetting>& out) {
  std::vector<BenchSetting> partial{BenchSetting{mounting, {}}};
  for (std::size_t k = 0; k < axes.size(); ++k) {
    std::vector<BenchSetting> next;
    for (const double v : axis_values(axes[k], solved[k]))
      for (BenchSetting s : partial) {
        s.angles.push_back(v);
        next.push_back(std::move(s));
      }
    partial = std::move(next);
  }
  out.insert(out.end(), partial.begin(), partial.end());
}

}  // namespace scalcal
