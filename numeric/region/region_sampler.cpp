// Random positions uniform on a restricted bench (region_sampler.hpp).
#include "numeric/region/region_sampler.hpp"

#include <cmath>
#include <numbers>

#include "numeric/synthesis/random_search_kernel.hpp"

namespace scalcal {
namespace {

// Uniform doubles in [0, 1) from the generator's 64-bit words, four at a time (top 53 bits).
class Uniforms {
 public:
  explicit Uniforms(Xoshiro256x4& rng) : rng_(rng) {}
  double operator()() {
    if (next_ == 4) {
      rng_.next(words_);
      next_ = 0;
    }
    return static_cast<double>(words_[next_++] >> 11) * 0x1.0p-53;
  }

 private:
  Xoshiro256x4& rng_;
  Xoshiro256x4::Words words_{};
  int next_ = 4;
};

struct ZoneDraw {
  Zone zone;
  Vec3 e1, e2;
  double z_lo, z_hi, cumulative;  // cumulative area share, ending at 1
};

}  // namespace

PositionSampler region_sampler(const Region& region) {
  const double deg = std::numbers::pi / 180.0;
  std::vector<ZoneDraw> zones;
  double total = 0;
  for (const Zone& z : region.zones) {
    const auto [e1, e2] = azimuth_frame(z.axis);
    const double lo = std::cos(z.max_tilt_deg * deg), hi = std::cos(z.min_tilt_deg * deg);
    total += hi - lo;
    zones.push_back({z, e1, e2, lo, hi, total});
  }
  for (auto& z : zones) z.cumulative /= total;
  return [zones, region](Xoshiro256x4& rng, int n, double* x, double* y, double* z) {
    Uniforms u(rng);
    const auto in_zone = [&]() -> Vec3 {
      for (;;) {
        const double pick = u();
        std::size_t k = 0;
        while (k + 1 < zones.size() && pick >= zones[k].cumulative) ++k;
        const ZoneDraw& d = zones[k];
        const double h = d.z_lo + (d.z_hi - d.z_lo) * u(), phi = 2 * std::numbers::pi * u();
        const double r = std::sqrt(std::max(0.0, 1 - h * h));
        const Vec3 p = r * (std::cos(phi) * d.e1 + std::sin(phi) * d.e2) + h * d.zone.axis;
        int holders = 0;
        for (const ZoneDraw& o : zones) holders += o.zone.contains(p, 0.0) ? 1 : 0;
        if (holders <= 1 || u() * holders < 1.0) return p;
      }
    };
    for (int i = 0; i < n; ++i) {
      const bool candidate = zones.empty() || (!region.candidates.empty() && u() < 0.5);
      const Vec3 p =
          candidate ? region.candidates[static_cast<std::size_t>(u() * static_cast<double>(region.candidates.size()))]
                    : in_zone();
      x[i] = p(0);
      y[i] = p(1);
      z[i] = p(2);
    }
    for (int i = n; i < sample_buffer_size(n); ++i) x[i] = y[i] = z[i] = 0.0;
  };
}

}  // namespace scalcal
