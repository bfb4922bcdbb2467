// The registered benches: one line each in RegisteredBenches. A Bench is the runtime handle (one of
// their values, parsed from a --bench spec); it answers through the BenchType members only, so the
// planner never asks which bench it holds.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "numeric/bench/faces.hpp"
#include "numeric/bench/gimbal.hpp"
#include "numeric/bench/jig.hpp"
#include "numeric/bench/rate_table.hpp"
#include "numeric/bench/tilt.hpp"
#include "numeric/io/input_error.hpp"

namespace scalcal {

template <BenchType... Bs>
struct BenchList {
  using Variant = std::variant<Bs...>;
};

using RegisteredBenches = BenchList<GimbalBench, TiltBench, FacesBench, JigBench, RateTableBench>;

class Bench {
  template <class F>
  decltype(auto) visit(F&& f) const {
    return std::visit(std::forward<F>(f), bench_);
  }

 public:
  explicit Bench(RegisteredBenches::Variant bench) : bench_(std::move(bench)) {}

  std::string text() const {
    return visit([](const auto& b) { return std::string(b.text()); });
  }
  std::string_view name() const {
    return visit([](const auto& b) { return std::string_view(std::decay_t<decltype(b)>::name); });
  }
  std::string_view mounting_key() const {
    return visit([](const auto& b) { return std::string_view(std::decay_t<decltype(b)>::mounting_key); });
  }
  bool angles_as_array() const {
    return visit([](const auto& b) { return bench_angles_as_array<std::decay_t<decltype(b)>>(); });
  }
  const std::vector<BenchAxis>& axes() const {
    return visit([](const auto& b) -> const std::vector<BenchAxis>& { return b.axes(); });
  }
  const std::vector<Mounting>& mountings() const {
    return visit([](const auto& b) -> const std::vector<Mounting>& { return b.mountings(); });
  }
  Mat3 orientation(const BenchSetting& s) const {
    return visit([&](const auto& b) { return b.orientation(s); });
  }
  Vec3 position(const BenchSetting& s) const { return position_of_orientation(orientation(s)); }
  std::vector<BenchSetting> settings(const Vec3& eta) const {
    return visit([&](const auto& b) { return b.settings(eta); });
  }
  double travel(const BenchSetting& a, const BenchSetting& c) const {
    return visit([&](const auto& b) { return bench_travel(b, a, c); });
  }
  bool remount(const BenchSetting& a, const BenchSetting& c) const {
    return visit([&](const auto& b) { return bench_remount(b, a, c); });
  }

 private:
  RegisteredBenches::Variant bench_;
};

namespace detail {
template <class... Bs>
std::optional<Bench> parse_bench(std::string_view name, std::string_view params, BenchList<Bs...>) {
  std::optional<Bench> out;
  ((!out && name == Bs::name ? (void)out.emplace(Bs::parse(params)) : (void)0), ...);
  return out;
}
template <class... Bs>
std::string bench_syntaxes(BenchList<Bs...>) {
  std::string s;
  ((s += (s.empty() ? "" : " | ") + std::string(Bs::syntax)), ...);
  return s;
}
}  // namespace detail

// "gimbal:A1,A2[,A3][:limits=...] | tilt:DEG[:flip] | faces[:DEG] | jig:NAME", for help lines.
inline std::string bench_syntaxes() { return detail::bench_syntaxes(RegisteredBenches{}); }

// A --bench spec: NAME or NAME:PARAMS. Throws InputError ("--bench", the spec, the reason).
inline Bench parse_bench(const std::string& spec) {
  const auto colon = spec.find(':');
  const std::string name = spec.substr(0, colon);
  const std::string params = colon == std::string::npos ? "" : spec.substr(colon + 1);
  std::optional<Bench> b = detail::parse_bench(name, params, RegisteredBenches{});
  if (!b) bench_error(spec, "unknown bench '" + display_name(name) + "'; one of " + bench_syntaxes());
  return *b;
}

}  // namespace scalcal
